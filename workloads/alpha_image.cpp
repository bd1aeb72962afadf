#include "workloads/alpha_image.h"

#include "traces/error.h"

namespace rtsim {
namespace {

AlphaImageReader reader = nullptr;

}  // namespace

void set_alpha_image_reader(AlphaImageReader r) {
  reader = r;
}

AlphaImage read_alpha_image(const std::string& name, const std::vector<uint8_t>& bytes) {
  if (!reader)
    throw_input_error(name, "", "this program cannot read texture images (no OpenImageIO)");
  return reader(name, bytes);
}

}  // namespace rtsim
