#include "traces/instance_settings.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace rtsim {
namespace {

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string motion_problem(const Motion& m) {
  if (m.keys.empty()) return "has no keys";
  if (!finite(m.axis) || std::fabs(glm::length(m.axis) - 1.0f) > 1e-4f)
    return "has an axis that is not of unit length";
  for (size_t k = 0; k < m.keys.size(); ++k) {
    const MotionKey& key = m.keys[k];
    if (!finite(key.translate) || !std::isfinite(key.rotate))
      return fmt::format("key {} is not finite", k);
    if (!(key.scale > 0.0f) || !std::isfinite(key.scale))
      return fmt::format("key {} has scale {:g}, not positive", k, key.scale);
  }
  return "";
}

template <typename Second>
std::string index_problem(const std::vector<std::pair<uint32_t, Second>>& list, size_t instances,
                          const char* what) {
  for (size_t i = 0; i < list.size(); ++i) {
    if (list[i].first >= instances)
      return fmt::format("{} of instance {}, of {} instances", what, list[i].first, instances);
    if (i > 0 && list[i].first <= list[i - 1].first)
      return fmt::format("{} of instance {} out of order", what, list[i].first);
  }
  return "";
}

}  // namespace

bool InstanceSettings::empty() const {
  return masks.empty() && moving.empty() &&
         std::all_of(ray_masks.begin(), ray_masks.end(),
                     [](uint8_t m) { return m == kAllInstances; });
}

bool InstanceSettings::operator==(const InstanceSettings& o) const {
  auto same_key = [](const MotionKey& a, const MotionKey& b) {
    return a.translate == b.translate && a.rotate == b.rotate && a.scale == b.scale;
  };
  auto same_motion = [&](const Motion& a, const Motion& b) {
    return a.axis == b.axis &&
           std::equal(a.keys.begin(), a.keys.end(), b.keys.begin(), b.keys.end(), same_key);
  };
  return ray_masks == o.ray_masks && masks == o.masks && moving == o.moving && frames == o.frames &&
         std::equal(motions.begin(), motions.end(), o.motions.begin(), o.motions.end(),
                    same_motion);
}

std::string settings_problem(const InstanceSettings& s, size_t instances) {
  for (int t = 0; t < kRayTypeCount; ++t)
    if (s.ray_masks[size_t(t)] == 0)
      return fmt::format("{} rays have inclusion mask 0 (they would see nothing)",
                         ray_type_name(RayType(t)));
  if (std::string p = index_problem(s.masks, instances, "a mask"); !p.empty()) return p;
  if (std::string p = index_problem(s.moving, instances, "a motion"); !p.empty()) return p;
  for (const auto& [instance, motion] : s.moving)
    if (motion >= s.motions.size())
      return fmt::format("instance {} moves by motion {} of {}", instance, motion,
                         s.motions.size());
  for (size_t m = 0; m < s.motions.size(); ++m)
    if (std::string p = motion_problem(s.motions[m]); !p.empty())
      return fmt::format("motion {} {}", m, p);
  if (s.animated() && s.frames == 0) return "motion over no frames";
  return "";
}

KeyBlend blend_keys(float t, size_t keys) {
  float at = t * float(keys - 1);
  size_t i = std::min(size_t(at), keys - 1);
  return {i, std::min(i + 1, keys - 1), at - float(i)};
}

Transform pose_at(const Transform& placed, const Motion& motion, uint32_t frame, uint32_t frames) {
  const std::vector<MotionKey>& keys = motion.keys;
  float t = frames > 1 ? float(std::min(frame, frames - 1)) / float(frames - 1) : 0.0f;
  auto [i, j, f] = blend_keys(t, keys.size());
  glm::vec3 translate = glm::mix(keys[i].translate, keys[j].translate, f);
  float degrees = glm::mix(keys[i].rotate, keys[j].rotate, f);
  float scale = glm::mix(keys[i].scale, keys[j].scale, f);
  // About the instance's origin: world = R S (placed - origin) + origin + translate.
  glm::mat3 turn(glm::rotate(glm::mat4(1.0f), glm::radians(degrees), motion.axis));
  glm::mat3 linear = turn * scale;
  Transform out;
  out.linear = linear * placed.linear;
  out.offset = placed.offset + translate;
  return out;
}

void apply_masks(InstancedMesh& geometry, const InstanceSettings& settings) {
  for (Instance& instance : geometry.instances) instance.mask = kAllInstances;
  for (const auto& [instance, mask] : settings.masks) geometry.instances[instance].mask = mask;
}

std::vector<Instance> instances_at(const std::vector<Instance>& placed,
                                   const InstanceSettings& settings, uint32_t frame) {
  std::vector<Instance> out = placed;
  for (const auto& [instance, motion] : settings.moving)
    out[instance].to_world =
        pose_at(placed[instance].to_world, settings.motions[motion], frame, settings.frames);
  return out;
}

}  // namespace rtsim
