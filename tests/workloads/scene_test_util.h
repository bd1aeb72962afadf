// Helpers shared by the scene tests: a private temp folder, file writing, and an assertion that
// loading a spec fails with an InputError naming it.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "traces/error.h"
#include "workloads/scene.h"

namespace rtsim::test {

// A folder under /tmp removed with everything in it when the object dies.
class TempDir {
public:
  TempDir() {
    static int counter = 0;
    path_ = std::filesystem::temp_directory_path() /
            ("rtsim-scenes-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  // Writes contents (text or bytes) to name inside the folder and returns the full path.
  std::string write(const std::string& name, const std::string& contents) const {
    std::string file = (path_ / name).string();
    std::ofstream(file, std::ios::binary) << contents;
    return file;
  }
  std::string path(const std::string& name) const { return (path_ / name).string(); }

private:
  std::filesystem::path path_;
};

// Loads spec expecting an InputError whose message starts with "spec: " (or "named: " when
// given) and contains fragment; returns the message.
inline std::string expect_input_error(const std::string& spec, const std::string& fragment,
                                      const std::string& named = "") {
  try {
    Scene scene = load_scene(spec);
    ADD_FAILURE() << "loading '" << spec << "' should fail, got " << scene.triangle_count()
                  << " triangles";
  } catch (const InputError& e) {
    std::string message = e.what();
    std::string prefix = (named.empty() ? spec : named) + ": ";
    EXPECT_EQ(message.rfind(prefix, 0), 0u) << "message should name the file: " << message;
    EXPECT_NE(message.find(fragment), std::string::npos)
        << "message should say '" << fragment << "': " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "message should be one line: " << message;
    return message;
  }
  return "";
}

}  // namespace rtsim::test
