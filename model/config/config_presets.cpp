#include "model/config/config_presets.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "traces/error.h"

namespace rtsim {
namespace fs = std::filesystem;

std::string configs_dir() {
  const char* dir = std::getenv("RTSIM_CONFIGS_DIR");
  return dir && *dir ? dir : RTSIM_CONFIGS_DIR;
}

std::vector<std::string> hw_config_presets() {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(configs_dir(), error))
    if (entry.path().extension() == ".toml" && entry.is_regular_file(error))
      names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string hw_config_path(const std::string& name) {
  std::error_code error;
  if (name.empty() || name.find('/') != std::string::npos ||
      fs::path(name).extension() == ".toml" || fs::exists(name, error))
    return name;
  std::string preset = configs_dir() + "/" + name + ".toml";
  if (fs::is_regular_file(preset, error)) return preset;
  throw_input_error(name, "",
                    fmt::format("no such file, nor a preset {} (presets: {})", preset,
                                fmt::join(hw_config_presets(), ", ")));
}

}  // namespace rtsim
