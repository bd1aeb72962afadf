// Alpha-tested geometry of the built-in scenes: unique meshes with masks, and the procedural
// leaf mask of their foliage.
#include <algorithm>
#include <cmath>

#include "workloads/builtin_scenes.h"

namespace rtsim::builtin {

void UniqueMesh::add(const MeshTemplate& t, const glm::vec3& offset, const glm::vec3& scale,
                     uint32_t material, const glm::mat3& rotation, uint32_t mask) {
  auto base = uint32_t(mesh.positions.size());
  for (const glm::vec3& p : t.positions) mesh.positions.push_back(offset + rotation * (scale * p));
  for (const auto& tri : t.triangles)
    mesh.triangles.push_back({base + tri[0], base + tri[1], base + tri[2]});
  materials.insert(materials.end(), t.triangles.size(), material);
  if (!alpha_) return;
  alpha_->mask_of.insert(alpha_->mask_of.end(), t.triangles.size(), mask);
  for (const auto& tri : t.triangles) {
    if (mask == TriangleAlpha::kOpaque)
      alpha_->uv.emplace_back();
    else
      alpha_->uv.push_back({t.uvs.at(tri[0]), t.uvs.at(tri[1]), t.uvs.at(tri[2])});
  }
}

uint32_t UniqueMesh::add_mask(std::shared_ptr<const AlphaMask> mask) {
  if (!alpha_) {
    alpha_ = std::make_shared<TriangleAlpha>();
    alpha_->mask_of.assign(mesh.triangle_count(), TriangleAlpha::kOpaque);
    alpha_->uv.resize(mesh.triangle_count());
    mesh.alpha = alpha_;
  }
  alpha_->masks.push_back(std::move(mask));
  return uint32_t(alpha_->masks.size() - 1);
}

void add_leaves(UniqueMesh& mesh, uint32_t leaves, float size, glm::vec3 centre, glm::vec3 radii,
                uint32_t material, uint32_t mask, Pcg32& rng) {
  const MeshTemplate leaf{{glm::vec3(0, size, 0), glm::vec3(-0.5f * size, -0.4f * size, 0),
                           glm::vec3(0.5f * size, -0.4f * size, 0)},
                          {{0, 1, 2}},
                          {kLeafUvs.begin(), kLeafUvs.end()}};
  for (uint32_t i = 0; i < leaves; ++i) {
    glm::vec3 u;
    do u = rng.symmetric_vector();
    while (u.x * u.x + u.y * u.y + u.z * u.z > 1.0f);
    mesh.add(leaf, centre + u * radii, glm::vec3(1.0f), material, random_rotation(rng), mask);
  }
}

std::shared_ptr<const AlphaMask> leaf_mask(const std::string& name, uint32_t size, float width,
                                           uint64_t texture_offset) {
  auto mask = std::make_shared<AlphaMask>();
  mask->name = name;
  mask->width = mask->height = size;
  mask->texture_offset = texture_offset;
  mask->alpha.resize(size_t(size) * size);
  // The blade runs from the tip at v = 0.05 to the stem at v = 0.85, half as wide as the
  // triangle where it is widest (v = 0.45) when width = 1; the stem goes on to the base.
  const float tip = 0.05f, length = 0.8f, stem = 0.015f;
  for (uint32_t y = 0; y < size; ++y) {
    float v = (float(y) + 0.5f) / float(size);
    float t = (v - tip) / length;
    float half = t < 0.0f ? 0.0f : t <= 1.0f ? 0.9f * width * t * (1.0f - t) : stem;
    for (uint32_t x = 0; x < size; ++x) {
      float u = (float(x) + 0.5f) / float(size);
      float inside = (half - std::abs(u - 0.5f)) * float(size) + 0.5f;  // texels, antialiased
      mask->alpha[size_t(y) * size + x] = uint8_t(255.0f * std::clamp(inside, 0.0f, 1.0f) + 0.5f);
    }
  }
  return mask;
}

}  // namespace rtsim::builtin
