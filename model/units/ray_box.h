// Ray-box unit: tests a ray against all child boxes of one decoded node (one node per unit
// pass; the timing model charges its latency per node). Slab test after Kay & Kajiya (1986),
// made conservative as Woop, Benthin & Wald (JCGT 2013, section 4.3) require for a watertight
// traversal: boxes are padded relative to the origin and scene magnitude (PreparedRay), and the
// far distance grows by 2*gamma(3) to cover the rounding of the slab arithmetic (Ize, "Robust
// BVH Ray Traversal", JCGT 2013). Direction components of +0 and -0 give reciprocals of +-inf;
// a 0 * inf NaN (origin exactly on a slab plane) is ignored by the NaN-dropping min/max, so the
// ray counts as inside that slab, which is the right answer for a closed box.
#pragma once

#include <cstdint>

#include "model/bvh/node_format.h"
#include "model/units/prepared_ray.h"

namespace rtsim {

// 1 + 2 * gamma(3) with gamma(n) = n u / (1 - n u), u = 2^-24, rounded up.
constexpr float kSlabFarGrowth =
    1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f) + 0x1p-23f;

// Hit slots as a bit mask; tnear[s] is where the ray enters the box of slot s (hit slots only).
// A box counts as hit where its (grown) span overlaps [ray.tmin, tmax]. All kMaxWidth slots are
// computed (slots past node.slots hold garbage and are masked off), so the loop vectorizes.
inline uint32_t intersect_children(const PreparedRay& ray, const NodeView& node, float tmax,
                                   float tnear[kMaxWidth]) {
  auto nan_max = [](float a, float b) { return a > b ? a : b; };  // b if a is NaN
  auto nan_min = [](float a, float b) { return a < b ? a : b; };
  const AliasedFloat* near_x = ray.near_is_hi[0] ? node.hi[0] : node.lo[0];
  const AliasedFloat* near_y = ray.near_is_hi[1] ? node.hi[1] : node.lo[1];
  const AliasedFloat* near_z = ray.near_is_hi[2] ? node.hi[2] : node.lo[2];
  const AliasedFloat* far_x = ray.near_is_hi[0] ? node.lo[0] : node.hi[0];
  const AliasedFloat* far_y = ray.near_is_hi[1] ? node.lo[1] : node.hi[1];
  const AliasedFloat* far_z = ray.near_is_hi[2] ? node.lo[2] : node.hi[2];
  int hit[kMaxWidth];
  for (int s = 0; s < kMaxWidth; ++s) {
    // Distances to the entry and exit planes of the three slabs.
    float enter_x = (near_x[s] - ray.org_near[0]) * ray.inv_dir[0];
    float enter_y = (near_y[s] - ray.org_near[1]) * ray.inv_dir[1];
    float enter_z = (near_z[s] - ray.org_near[2]) * ray.inv_dir[2];
    float leave_x = (far_x[s] - ray.org_far[0]) * ray.inv_dir[0];
    float leave_y = (far_y[s] - ray.org_far[1]) * ray.inv_dir[1];
    float leave_z = (far_z[s] - ray.org_far[2]) * ray.inv_dir[2];
    // Intersect the spans with the ray's; NaN (0 * inf) leaves a span unchanged.
    float t0 = nan_max(enter_x, nan_max(enter_y, nan_max(enter_z, ray.tmin)));
    float t1 = nan_min(leave_x, nan_min(leave_y, nan_min(leave_z, tmax)));
    tnear[s] = t0;
    hit[s] = t0 <= t1 * kSlabFarGrowth;
  }
  uint32_t hits = 0;
  for (int s = 0; s < kMaxWidth; ++s) hits |= uint32_t(hit[s]) << s;
  return hits & node.valid;
}

}  // namespace rtsim
