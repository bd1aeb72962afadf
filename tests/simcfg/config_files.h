// Config files for the loader's tests: written to the scratch folder, and the one-line error
// that loading one gives.
#pragma once

#include <fstream>
#include <string>
#include <vector>

#include "model/config/hw_config.h"
#include "tests/temp_dir.h"
#include "traces/error.h"

namespace rtsim::test {

inline std::string write_toml(const std::string& text) {
  static int n = 0;
  std::string path = scratch_path("config" + std::to_string(n++) + ".toml");
  std::ofstream(path) << text;
  return path;
}

// What load_hw_config says of the file and overrides ("(no error)" if it loads).
inline std::string error_of(const std::string& path, const std::vector<std::string>& sets = {}) {
  try {
    load_hw_config(path, sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace rtsim::test
