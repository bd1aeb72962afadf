// PNG output through OpenImageIO, written to a temporary name and renamed, so a failed run
// never leaves a half-written picture.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "workloads/alpha_image.h"

namespace rtsim::pipeline {

// rgb: width * height * 3 bytes, rows top to bottom. Throws InputError naming path on failure.
void write_png(const std::string& path, uint32_t width, uint32_t height,
               const std::vector<uint8_t>& rgb);

// The AlphaImageReader (workloads/alpha_image.h) of OpenImageIO: any format it reads (PNG and
// JPEG, glTF's two, among them), from a file or from memory.
AlphaImage read_texture_alpha(const std::string& name, const std::vector<uint8_t>& bytes);

}  // namespace rtsim::pipeline
