#include "traces/alpha.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

namespace rtsim {
namespace {

uint32_t texel(float coordinate, uint32_t size) {
  float wrapped = coordinate - std::floor(coordinate);
  return std::min(uint32_t(wrapped * float(size)), size - 1);
}

glm::vec2 at(const std::array<glm::vec2, 3>& c, float u, float v) {
  return (1.0f - u - v) * c[0] + u * c[1] + v * c[2];
}

}  // namespace

uint32_t AlphaMask::texel_at(glm::vec2 uv) const {
  return texel(uv.y, height) * width + texel(uv.x, width);
}

bool TriangleAlpha::passes(uint32_t tri, float u, float v) const {
  return !tested(tri) || look_up(tri, u, v).opaque;
}

TriangleAlpha::Lookup TriangleAlpha::look_up(uint32_t tri, float u, float v) const {
  const AlphaMask& mask = *masks[mask_of[tri]];
  uint32_t texel = mask.texel_at(at(uv[tri], u, v));
  return {mask.opaque(texel), mask.texture_offset + uint64_t(texel) * kTexelBytes};
}

std::string TriangleAlpha::problem(size_t triangles) const {
  if (mask_of.size() != triangles || uv.size() != triangles)
    return fmt::format("alpha for {} and texture coordinates for {} of {} triangles",
                       mask_of.size(), uv.size(), triangles);
  for (size_t t = 0; t < triangles; ++t) {
    if (mask_of[t] != kOpaque && mask_of[t] >= masks.size())
      return fmt::format("triangle {}: alpha mask {} of {}", t, mask_of[t], masks.size());
    for (const glm::vec2& c : uv[t])
      if (!std::isfinite(c.x) || !std::isfinite(c.y))
        return fmt::format("triangle {}: texture coordinate is NaN or Inf", t);
  }
  for (const auto& m : masks)
    if (!m || m->width == 0 || m->height == 0 || m->alpha.size() != size_t(m->width) * m->height)
      return fmt::format("alpha mask '{}' has no texels or the wrong count", m ? m->name : "");
  return {};
}

void append_alpha(TriangleAlpha& out, const TriangleAlpha* in, size_t triangles) {
  if (!in) {
    out.mask_of.insert(out.mask_of.end(), triangles, TriangleAlpha::kOpaque);
    out.uv.resize(out.uv.size() + triangles);
    return;
  }
  // A mask out already holds (another instance of the same mesh) keeps its one index.
  std::vector<uint32_t> index;
  for (const auto& mask : in->masks) {
    auto found = std::find(out.masks.begin(), out.masks.end(), mask);
    index.push_back(uint32_t(found - out.masks.begin()));
    if (found == out.masks.end()) out.masks.push_back(mask);
  }
  for (uint32_t m : in->mask_of) out.mask_of.push_back(m == TriangleAlpha::kOpaque ? m : index[m]);
  out.uv.insert(out.uv.end(), in->uv.begin(), in->uv.end());
}

}  // namespace rtsim
