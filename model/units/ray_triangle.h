// Ray-triangle unit: one triangle per test (the timing model charges its latency per test).
//  - raw records: the watertight test of Woop, Benthin & Wald, "Watertight Ray/Triangle
//    Intersection" (JCGT 2013): vertices are translated to the ray origin and sheared so the
//    ray runs along +z; the 2D edge functions decide inside/outside, recomputed in double when
//    one of them is exactly 0, so a ray through a shared edge or vertex hits at least one
//    triangle. Backfaces hit; degenerate triangles never do. The distance comes from the plane
//    equation (as in Embree's robust test) rather than the paper's interpolated z, which loses
//    digits on sliver triangles.
//  - woop records: the unit-triangle test of Woop, "Ray Tracing Hardware Architecture" (2004)
//    on a precomputed affine map; not watertight.
//  - amd_tri records (radv_bvh_triangle_node): the watertight test on their vertices; the id
//    is at byte 48.
// A hit needs tmin <= t <= tmax (t in the units of the prepared ray).
#pragma once

#include <cstdint>
#include <cstring>

#include "model/bvh/bvh_config.h"
#include "model/bvh/intel_nodes.h"
#include "model/units/prepared_ray.h"

namespace rtsim {

struct TriangleHit {
  float t = 0.0f;
  float u = 0.0f, v = 0.0f;  // barycentrics of vertices 1 and 2
};

// Tests run inline in the traversal loop: they are the hot path of every model run.
inline bool intersect_watertight(const PreparedRay& ray, const float vertices[9], float tmin,
                                 float tmax, TriangleHit& hit) {
  // Translate the vertices to the ray origin.
  float a[3], b[3], c[3];
  for (int i = 0; i < 3; ++i) {
    a[i] = vertices[i] - ray.org[i];
    b[i] = vertices[3 + i] - ray.org[i];
    c[i] = vertices[6 + i] - ray.org[i];
  }
  // Shear so the ray runs along +z and project onto the xy plane.
  float ax = a[ray.kx] - ray.sx * a[ray.kz], ay = a[ray.ky] - ray.sy * a[ray.kz];
  float bx = b[ray.kx] - ray.sx * b[ray.kz], by = b[ray.ky] - ray.sy * b[ray.kz];
  float cx = c[ray.kx] - ray.sx * c[ray.kz], cy = c[ray.ky] - ray.sy * c[ray.kz];
  // Scaled barycentrics: 2D edge functions of the origin against each edge.
  float u = cx * by - cy * bx;
  float v = ax * cy - ay * cx;
  float w = bx * ay - by * ax;
  // On an edge in fp32: decide it in double, where these products are exact.
  if (u == 0.0f || v == 0.0f || w == 0.0f) {
    u = static_cast<float>(double(cx) * double(by) - double(cy) * double(bx));
    v = static_cast<float>(double(ax) * double(cy) - double(ay) * double(cx));
    w = static_cast<float>(double(bx) * double(ay) - double(by) * double(ax));
  }
  // Outside if the edge functions disagree in sign; degenerate if they sum to 0.
  if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return false;
  float det = u + v + w;
  if (det == 0.0f) return false;
  // Distance from the plane equation, accurate also for slivers (as Embree's robust test).
  const float* v0 = vertices;
  float e1[3] = {vertices[3] - v0[0], vertices[4] - v0[1], vertices[5] - v0[2]};
  float e2[3] = {vertices[6] - v0[0], vertices[7] - v0[1], vertices[8] - v0[2]};
  float n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                e1[0] * e2[1] - e1[1] * e2[0]};
  float t = (n[0] * a[0] + n[1] * a[1] + n[2] * a[2]) /
            (n[0] * ray.dir[0] + n[1] * ray.dir[1] + n[2] * ray.dir[2]);
  if (!(t >= tmin && t <= tmax)) return false;
  float inv_det = 1.0f / det;
  hit.t = t;
  hit.u = v * inv_det;
  hit.v = w * inv_det;
  return true;
}

inline bool intersect_woop(const PreparedRay& ray, const float rows[12], float tmin, float tmax,
                           TriangleHit& hit) {
  auto apply = [&](int row, const glm::vec3& p, float w) {
    const float* r = rows + 4 * row;
    return r[0] * p.x + r[1] * p.y + r[2] * p.z + r[3] * w;
  };
  // Distance to the plane z = 0 of the unit-triangle space.
  float oz = apply(2, ray.org, 1.0f), dz = apply(2, ray.dir, 0.0f);
  float t = -oz / dz;
  if (!(t >= tmin && t <= tmax)) return false;
  // Barycentrics where the ray meets that plane.
  float u = apply(0, ray.org, 1.0f) + t * apply(0, ray.dir, 0.0f);
  if (!(u >= 0.0f && u <= 1.0f)) return false;
  float v = apply(1, ray.org, 1.0f) + t * apply(1, ray.dir, 0.0f);
  if (!(v >= 0.0f && u + v <= 1.0f)) return false;
  hit.t = t;
  hit.u = u;
  hit.v = v;
  return true;
}

// Tests triangle `part` of a record (0; an xe_quad's second triangle: 1).
inline bool intersect_triangle(TriangleFormat format, const PreparedRay& ray, const uint8_t* bytes,
                               uint32_t part, float tmin, float tmax, TriangleHit& hit,
                               uint32_t& prim) {
  float values[12];
  if (format == TriangleFormat::XeQuad) {  // the watertight test on the quad's corners
    uint32_t id = xe_quad_corners(bytes, part, values);
    bool found = intersect_watertight(ray, values, tmin, tmax, hit);
    if (found) prim = id;
    return found;
  }
  bool woop = format == TriangleFormat::Woop;
  std::memcpy(values, bytes, woop ? 48 : 36);
  bool found = woop ? intersect_woop(ray, values, tmin, tmax, hit)
                    : intersect_watertight(ray, values, tmin, tmax, hit);
  // The id follows the vertices (raw), the rows (woop) or sits at byte 48 (amd_tri).
  if (found)
    std::memcpy(&prim, bytes + (woop || format == TriangleFormat::AmdTriangle ? 48 : 36), 4);
  return found;
}

}  // namespace rtsim
