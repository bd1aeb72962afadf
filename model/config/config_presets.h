// Hardware presets by name: `--config desktop` (and a sweep spec's or suite's `config =
// "desktop"`) reads configs/desktop.toml of rtsim's own configs folder (RTSIM_CONFIGS_DIR in the
// environment overrides where that is), wherever the command runs.
#pragma once

#include <string>
#include <vector>

namespace rtsim {

// The folder of the presets.
std::string configs_dir();

// The preset names (the .toml files of configs_dir(), not its subfolders), sorted.
std::vector<std::string> hw_config_presets();

// The file a config argument names: itself where it is a file, names a folder ('/') or ends in
// .toml; else the preset configs_dir()/NAME.toml. Throws InputError naming the argument and
// listing the presets where it is neither. "" (the built-in defaults) stays "".
std::string hw_config_path(const std::string& name);

}  // namespace rtsim
