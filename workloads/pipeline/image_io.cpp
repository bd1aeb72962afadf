#include "workloads/pipeline/image_io.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fmt/format.h>

#include "traces/error.h"
#include "traces/memory_plan.h"
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
  if (ok && output.commit()) return;
  if (error.empty() && !ok) error = out->geterror();
  if (error.empty()) error = std::strerror(errno);  // a failed rename, or a close naming no reason
  output.discard();
  throw_input_error(path, "", "cannot write image: " + error);
}

AlphaImage read_texture_alpha(const std::string& name, const std::vector<uint8_t>& bytes) {
  OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
  auto in = OIIO::ImageInput::open(name, nullptr, bytes.empty() ? nullptr : &memory);
  if (!in) throw_input_error(name, "", "cannot read the texture image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  AlphaImage image;
  image.width = uint32_t(spec.width);
  image.height = uint32_t(spec.height);
  uint64_t texels = uint64_t(image.width) * image.height;
  if (texels == 0) throw_input_error(name, "", "the texture image has no pixels");
  require_memory(texels, name, fmt::format("a {}x{} texture's alpha", spec.width, spec.height),
                 "use a smaller texture");
  image.alpha.assign(texels, 255);
  int a = spec.alpha_channel;
  if (a >= 0 && !in->read_image(0, 0, a, a + 1, OIIO::TypeDesc::UINT8, image.alpha.data()))
    throw_input_error(name, "", "cannot read the texture image: " + in->geterror());
  return image;
}

}  // namespace rtsim::pipeline
