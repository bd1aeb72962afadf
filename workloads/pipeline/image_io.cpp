#include "workloads/pipeline/image_io.h"

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <cstdio>

#include "traces/error.h"
#include "traces/output_file.h"

namespace rtsim::pipeline {

void write_png(const std::string& path, uint32_t width, uint32_t height,
               const std::vector<uint8_t>& rgb) {
  OutputFile output(path);
  auto out = OIIO::ImageOutput::create("png");
  if (!out) throw_input_error(path, "", "OpenImageIO has no PNG writer: " + OIIO::geterror());
  OIIO::ImageSpec spec(int(width), int(height), 3, OIIO::TypeDesc::UINT8);
  bool ok =
      out->open(output.write_path(), spec) && out->write_image(OIIO::TypeDesc::UINT8, rgb.data());
  std::string error = ok ? "" : out->geterror();
  ok = out->close() && ok;
  if (!ok || !output.commit()) {
    output.discard();
    throw_input_error(path, "", "cannot write image: " + (error.empty() ? "rename failed" : error));
  }
}

}  // namespace rtsim::pipeline
