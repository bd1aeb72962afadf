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
constexpr float kSlabFarGrowth = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f) +
                                 0x1p-23f;

// Hit slots as a bit mask; tnear[s] is where the ray enters the box of slot s (hit slots only).
// A box counts as hit where its (grown) span overlaps [ray.tmin, tmax].
inline uint32_t intersect_children(const PreparedRay& ray, const NodeView& node, float tmax,
                                   float tnear[kMaxWidth]) {
  const float* near_plane[3];
  const float* far_plane[3];
  for (int a = 0; a < 3; ++a) {
    near_plane[a] = ray.near_is_hi[a] ? node.hi[a] : node.lo[a];
    far_plane[a] = ray.near_is_hi[a] ? node.lo[a] : node.hi[a];
  }
  float t_limit = tmax * kSlabFarGrowth;
  uint32_t hits = 0;
  for (int s = 0; s < node.slots; ++s) {
    float t0 = ray.tmin, t1 = t_limit;
    for (int a = 0; a < 3; ++a) {
      // Distances to the entry and exit planes of this slab.
      float enter = (near_plane[a][s] - ray.org_near[a]) * ray.inv_dir[a];
      float leave = (far_plane[a][s] - ray.org_far[a]) * ray.inv_dir[a] * kSlabFarGrowth;
      // Narrow the span; a NaN comparison is false, so NaN leaves the span as it is.
      t0 = enter > t0 ? enter : t0;
      t1 = leave < t1 ? leave : t1;
    }
    tnear[s] = t0;
    hits |= uint32_t(t0 <= t1) << s;
  }
  return hits & node.valid;
}

}  // namespace rtsim
