// Double-precision arbiter: when the model and Embree disagree on a ray, recomputes the disputed
// triangle in double precision and says why they may disagree and which side is right.
// Classes: the ray passes through an edge or vertex (shared or not), grazes the triangle's
// plane, the triangle is degenerate (zero area or a needle), two triangles are hit at the same
// t, the hit lies at the end of the ray's [tmin, tmax], or it lies on a texel edge of an
// alpha-tested triangle's mask. Anything else is unexplained: a bug.
// Not a hardware unit: a checking tool with no timing.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "traces/embree_scene.h"
#include "traces/instances.h"
#include "traces/ray.h"

namespace rtsim {

enum class MismatchClass : uint8_t {
  EdgeOrVertex,   // ray within edge_epsilon of an edge or vertex of the disputed triangle
  Grazing,        // ray (nearly) parallel to the disputed triangle's plane, or t differs
                  // within the fp32 error bound amplified by 1 / cos(angle to the plane)
  Degenerate,     // disputed triangle of (nearly) zero area
  EqualTTie,      // both hit, different triangles, same t within tolerance
  RangeBoundary,  // the disputed hit lies at tmin or tmax within range_epsilon
  AlphaEdge,      // the hit's texture coordinates lie on a texel edge of an alpha mask, where
                  // fp32 and exact barycentrics may pick texels of different opacity
  Unexplained,
};
constexpr int kMismatchClassCount = 7;
const char* mismatch_class_name(MismatchClass c);

enum class RightSide : uint8_t {
  Model,   // exact arithmetic agrees with the model
  Embree,  // exact arithmetic agrees with Embree
  Both,    // either answer is correct within the precision of the question (edges, ties)
};
constexpr int kRightSideCount = 3;
const char* right_side_name(RightSide side);

struct ArbiterConfig {
  double edge_epsilon = 1e-5;      // normalized barycentric below which a point is on an edge
  double graze_cosine = 1e-4;      // |cos(ray, plane normal)| below which a ray grazes
  double degenerate_ratio = 1e-7;  // 2*area / longest edge^2 below which a triangle degenerates
  double range_epsilon = 1e-5;     // relative distance of t to tmin or tmax at the boundary
  double t_tolerance = 1e-5;       // relative t difference under which two hits agree
};

// The disputed triangle recomputed in double: translated to the origin and sheared like the
// watertight test, with exact-enough edge functions.
struct ExactHit {
  bool inside = false;    // every normalized barycentric >= 0 and the plane is crossed
  bool in_range = false;  // and tmin <= t <= tmax
  double t = 0.0;
  double min_barycentric = 0.0;  // signed, normalized: < 0 outside, ~0 on an edge
  double u = 0.0, v = 0.0;       // barycentrics of corners 1 and 2
  double cosine = 0.0;           // |cos| between the ray and the plane normal
  double area_ratio = 0.0;       // 2 * area / longest edge^2
  // How far from an edge, in normalized barycentrics, an fp32 test can err: rounding of the
  // vertices translated to the ray origin (ulps of the largest coordinate over the triangle's
  // height) and of the edge functions (ulps over area_ratio).
  double edge_error = 0.0;
  // Alpha-tested triangles (set by the arbiter): whether the mask is opaque at the exact
  // barycentrics, and whether a step of edge_epsilon (or edge_error) in them reaches a texel of
  // the other opacity.
  bool opaque = true;
  bool alpha_edge = false;
  bool hit() const { return inside && in_range && opaque; }
  bool near_edge(double edge_epsilon) const {
    return std::fabs(min_barycentric) < std::max(edge_epsilon, edge_error);
  }
};

ExactHit exact_intersect(const FlatTriangles& triangles, uint64_t prim, const Ray& ray);

// True if a and b are the same distance within the tolerance of fp32 hit computation:
// relative t_tolerance plus a few ulps of the coordinates' magnitude along the ray.
bool same_t(double a, double b, const Ray& ray, double t_tolerance);

struct Verdict {
  bool agree = true;
  MismatchClass cls = MismatchClass::Unexplained;
  RightSide right = RightSide::Both;
  uint32_t disputed = kNoHit;  // the triangle the verdict rests on
};

class Arbiter {
 public:
  // triangles: the scene by flat id; embree: Embree over the same scene, flat or instanced
  // (its hits are mapped to flat ids).
  Arbiter(FlatTriangles triangles, const EmbreeScene& embree, ArbiterConfig config = {});

  // Compares one ray's answers. model_prim is the triangle the model hit, also for any-hit
  // queries (kNoHit on a miss); embree is EmbreeScene::trace's answer.
  Verdict judge(const Ray& ray, const Hit& embree, uint32_t model_prim, float model_t) const;
  const FlatTriangles& triangles() const { return triangles_; }

 private:
  Verdict classify(const Ray& ray, uint32_t prim, bool model_reported, double other_t) const;
  // exact_intersect, with the alpha mask of an alpha-tested triangle applied.
  ExactHit exact(uint32_t prim, const Ray& ray) const;
  uint32_t find_candidate(const Ray& ray) const;

  FlatTriangles triangles_;
  const EmbreeScene& embree_;
  ArbiterConfig config_;
};

}  // namespace rtsim
