// The alpha channel of a texture image, for the alpha-tested (glTF alphaMode MASK) materials of
// scene files. OpenImageIO reads it, in the programs that link it (rtsim sets its reader,
// workloads/pipeline/image_io.h): its 250 shared libraries would cost every test process that
// loads a scene 0.4 s.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rtsim {

struct AlphaImage {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> alpha;  // rows top to bottom; 255 everywhere for an image without alpha
};

// Reads the image file `name`, or, when bytes is not empty, the image file held in bytes (name
// then only names it, and its extension gives the format). Throws InputError naming name.
using AlphaImageReader = AlphaImage (*)(const std::string& name, const std::vector<uint8_t>& bytes);

void set_alpha_image_reader(AlphaImageReader reader);
// Through the reader set; InputError naming name if none is.
AlphaImage read_alpha_image(const std::string& name, const std::vector<uint8_t>& bytes);

}  // namespace rtsim
