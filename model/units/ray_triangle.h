// Ray-triangle unit: one triangle per test (the timing model charges its latency per test).
//  - raw records: the watertight test of Woop, Benthin & Wald, "Watertight Ray/Triangle
//    Intersection" (JCGT 2013): vertices are translated to the ray origin and sheared so the
//    ray runs along +z; the 2D edge functions decide inside/outside, recomputed in double when
//    one of them is exactly 0, so a ray through a shared edge or vertex hits at least one
//    triangle. Backfaces hit; degenerate triangles never do.
//  - woop records: the unit-triangle test of Woop, "Ray Tracing Hardware Architecture" (2004)
//    on a precomputed affine map; not watertight.
// A hit needs tmin <= t <= tmax (t in the units of the prepared ray).
#pragma once

#include <cstdint>

#include "model/bvh/bvh_config.h"
#include "model/units/prepared_ray.h"

namespace rtsim {

struct TriangleHit {
  float t = 0.0f;
  float u = 0.0f, v = 0.0f;  // barycentrics of vertices 1 and 2
};

bool intersect_watertight(const PreparedRay& ray, const float vertices[9], float tmin, float tmax,
                          TriangleHit& hit);
bool intersect_woop(const PreparedRay& ray, const float rows[12], float tmin, float tmax,
                    TriangleHit& hit);

// Tests the record at `bytes` in the given format; writes its primitive id on a hit.
bool intersect_triangle(TriangleFormat format, const PreparedRay& ray, const uint8_t* bytes,
                        float tmin, float tmax, TriangleHit& hit, uint32_t& prim);

}  // namespace rtsim
