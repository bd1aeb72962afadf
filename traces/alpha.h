// Alpha-tested triangles (glTF alphaMode MASK; the leaves and fences of built-in scenes): a
// candidate hit on one counts only where its mask's alpha at the hit's texture coordinates
// reaches the mask's cutoff. Elsewhere the ray goes on through, as it does on a GPU whose any-hit
// shader ignores the candidate. The model's traversal and Embree's reference (an intersection
// filter) both ask TriangleAlpha::passes, so they agree but where their barycentrics fall on
// opposite sides of a texel edge.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

namespace rtsim {

// An alpha channel, nearest-texel lookup, repeating outside [0, 1) (glTF's default sampler
// wrap); texel row 0 at v = 0, the top of the image as glTF places it.
struct AlphaMask {
  std::string name;  // the texture file or the generator, for messages
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> alpha;  // width x height, row after row
  float cutoff = 0.5f;         // glTF alphaCutoff: alpha / 255 below it is a hole
  // Where the timing model keeps the mask's texture (RGBA8, kTexelBytes a texel, row after
  // row): bytes from the start of the texture region (model/mem/memory_level.h kTextureBase),
  // set by the scene that makes the mask (textures of one scene must not overlap).
  uint64_t texture_offset = 0;

  // The texel a texture coordinate reads: row * width + column.
  uint32_t texel_at(glm::vec2 uv) const;
  bool opaque(uint32_t texel) const { return float(alpha[texel]) >= cutoff * 255.0f; }
  bool opaque_at(glm::vec2 uv) const { return opaque(texel_at(uv)); }
};

constexpr uint32_t kTexelBytes = 4;  // a texel of the base colour texture the mask comes from

// The alpha-tested triangles of one TriangleMesh.
struct TriangleAlpha {
  static constexpr uint32_t kOpaque = UINT32_MAX;
  std::vector<std::shared_ptr<const AlphaMask>> masks;
  std::vector<uint32_t> mask_of;             // per triangle: index into masks, or kOpaque
  std::vector<std::array<glm::vec2, 3>> uv;  // per triangle: its corners' texture coordinates

  bool tested(uint32_t tri) const { return mask_of[tri] != kOpaque; }
  // True if a hit at barycentrics (u, v) of vertices 1 and 2 of triangle tri counts.
  bool passes(uint32_t tri, float u, float v) const;
  // An alpha-tested triangle's lookup at (u, v): whether it counts, and the texel that decides
  // as a byte offset into the texture region (what the any-hit shader reads).
  struct Lookup {
    bool opaque;
    uint64_t texel_offset;
  };
  Lookup look_up(uint32_t tri, float u, float v) const;
  // Why the arrays cannot serve a mesh of `triangles` triangles; empty if they can.
  std::string problem(size_t triangles) const;
};

// Appends the alpha of a mesh of `triangles` triangles (null: all opaque) after out's, as
// flatten() appends instances; the masks are shared, each held once.
void append_alpha(TriangleAlpha& out, const TriangleAlpha* in, size_t triangles);

}  // namespace rtsim
