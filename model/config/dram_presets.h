// The DRAM presets of configs/dram/ (GDDR6, LPDDR5, HBM3, DDR5), compiled into the binary so
// that `dram.preset = "gddr6-16"` works from any folder. Each is a TOML document of [dram] and
// [dram.timing] keys, every number with its source (configs/dram/SOURCES.md).
#pragma once

#include <string>
#include <vector>

namespace rtsim {

struct DramPreset {
  const char* name;  // the file name without .toml
  const char* toml;  // the file's text
};

const std::vector<DramPreset>& dram_presets();
std::vector<std::string> dram_preset_names();

}  // namespace rtsim
