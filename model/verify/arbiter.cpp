#include "model/verify/arbiter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <glm/geometric.hpp>

namespace rtsim {
namespace {

constexpr double kFloatEpsilon = 0x1p-24;  // half an fp32 ulp at 1

double max_abs(const glm::dvec3& v) {
  return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}

// Absolute slack of an fp32 hit distance: a few ulps of the coordinates along the ray.
double t_slack(const Ray& ray, double t) {
  glm::dvec3 o(ray.org), d(ray.dir);
  double scale = std::max(max_abs(o), std::isfinite(t) ? max_abs(o + t * d) : 0.0);
  return 32.0 * kFloatEpsilon * scale / max_abs(d);
}

}  // namespace

const char* mismatch_class_name(MismatchClass c) {
  switch (c) {
    case MismatchClass::EdgeOrVertex: return "edge_or_vertex";
    case MismatchClass::Grazing: return "grazing";
    case MismatchClass::Degenerate: return "degenerate";
    case MismatchClass::EqualTTie: return "equal_t_tie";
    case MismatchClass::RangeBoundary: return "range_boundary";
    case MismatchClass::AlphaEdge: return "alpha_edge";
    default: return "unexplained";
  }
}

const char* right_side_name(RightSide side) {
  switch (side) {
    case RightSide::Model: return "model";
    case RightSide::Embree: return "embree";
    default: return "both";
  }
}

ExactHit exact_intersect(const FlatTriangles& triangles, uint64_t prim, const Ray& ray) {
  ExactHit ex;
  glm::dvec3 o(ray.org), d(ray.dir);
  std::array<glm::vec3, 3> corners = triangles.corners(prim, ray.frame);
  glm::dvec3 v[3];
  for (int c = 0; c < 3; ++c) v[c] = glm::dvec3(corners[c]) - o;
  // Shape: normal, cosine with the ray, area against the longest edge.
  glm::dvec3 n = glm::cross(v[1] - v[0], v[2] - v[0]);
  double longest =
      std::max({glm::length(v[1] - v[0]), glm::length(v[2] - v[1]), glm::length(v[0] - v[2])});
  double n_len = glm::length(n);
  ex.area_ratio = longest > 0.0 ? n_len / (longest * longest) : 0.0;
  ex.cosine = n_len > 0.0 ? std::fabs(glm::dot(n, d)) / (n_len * glm::length(d)) : 0.0;
  if (ex.area_ratio > 0.0) {
    // An instance's triangle is tested in its object space on both sides, against a ray moved
    // there, while these corners were moved to the world: twice the rounding.
    const double kUlps = triangles.instanced() ? 8.0 : 4.0;
    double magnitude = max_abs(o);
    for (int c = 0; c < 3; ++c) magnitude = std::max(magnitude, max_abs(v[c] + o));
    ex.edge_error =
        kUlps * kFloatEpsilon * (magnitude / (ex.area_ratio * longest) + 1.0 / ex.area_ratio);
  }
  // Shear so the ray runs along +z, as the watertight test does, but in double.
  int kz = std::fabs(d.x) > std::fabs(d.y) ? (std::fabs(d.x) > std::fabs(d.z) ? 0 : 2)
                                           : (std::fabs(d.y) > std::fabs(d.z) ? 1 : 2);
  int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  double sx = d[kx] / d[kz], sy = d[ky] / d[kz], sz = 1.0 / d[kz];
  double px[3], py[3], pz[3];
  for (int c = 0; c < 3; ++c) {
    px[c] = v[c][kx] - sx * v[c][kz];
    py[c] = v[c][ky] - sy * v[c][kz];
    pz[c] = sz * v[c][kz];
  }
  // Edge functions, normalized to barycentrics.
  double e[3] = {px[2] * py[1] - py[2] * px[1], px[0] * py[2] - py[0] * px[2],
                 px[1] * py[0] - py[1] * px[0]};
  double det = e[0] + e[1] + e[2];
  if (det == 0.0 || !std::isfinite(det)) return ex;
  double b[3] = {e[0] / det, e[1] / det, e[2] / det};
  ex.min_barycentric = std::min({b[0], b[1], b[2]});
  ex.u = b[1];
  ex.v = b[2];
  ex.inside = ex.min_barycentric >= 0.0;
  ex.t = b[0] * pz[0] + b[1] * pz[1] + b[2] * pz[2];
  ex.in_range = ex.t >= ray.tmin && ex.t <= ray.tmax;
  return ex;
}

bool same_t(double a, double b, const Ray& ray, double t_tolerance) {
  if (a == b) return true;
  double diff = std::fabs(a - b);
  return diff <= t_tolerance * std::max(std::fabs(a), std::fabs(b)) ||
         diff <= t_slack(ray, std::max(a, b));
}

Arbiter::Arbiter(FlatTriangles triangles, const EmbreeScene& embree, ArbiterConfig config)
    : triangles_(std::move(triangles)), embree_(embree), config_(config) {}

ExactHit Arbiter::exact(uint32_t prim, const Ray& ray) const {
  ExactHit ex = exact_intersect(triangles_, prim, ray);
  uint32_t local = 0;
  const TriangleAlpha* alpha = triangles_.alpha(prim, local);
  if (!alpha || ray.force_opaque || !alpha->tested(local)) return ex;
  auto passes = [&](double u, double v) { return alpha->passes(local, float(u), float(v)); };
  ex.opaque = passes(ex.u, ex.v);
  double step = std::max(config_.edge_epsilon, ex.edge_error);
  for (double du : {-step, step})
    ex.alpha_edge |= passes(ex.u + du, ex.v) != ex.opaque || passes(ex.u, ex.v + du) != ex.opaque;
  return ex;
}

Verdict Arbiter::classify(const Ray& ray, uint32_t prim, bool model_reported,
                          double other_t) const {
  Verdict out{false, MismatchClass::Unexplained, RightSide::Both, prim};
  ExactHit ex = exact(prim, ray);
  double slack = t_slack(ray, ex.t);
  bool near_edge = ex.near_edge(config_.edge_epsilon);
  bool at_tmin = std::fabs(ex.t - ray.tmin) <= config_.range_epsilon * std::fabs(ex.t) + slack;
  bool at_tmax = std::isfinite(ray.tmax) &&
                 std::fabs(ex.t - ray.tmax) <= config_.range_epsilon * std::fabs(ex.t) + slack;
  if (ex.area_ratio < config_.degenerate_ratio)
    out.cls = MismatchClass::Degenerate;
  else if (ex.cosine < config_.graze_cosine)
    out.cls = MismatchClass::Grazing;
  else if (near_edge)
    out.cls = MismatchClass::EdgeOrVertex;
  else if (at_tmin || at_tmax)
    out.cls = MismatchClass::RangeBoundary;
  else if (ex.alpha_edge && ex.inside)
    out.cls = MismatchClass::AlphaEdge;
  // The side whose claim exact arithmetic supports is right; on the boundary, either is.
  bool claim_holds = std::isnan(other_t) ? ex.hit() : ex.hit() && ex.t < other_t;
  bool on_boundary = std::fabs(ex.min_barycentric) < 1e-9 || out.cls == MismatchClass::AlphaEdge ||
                     (at_tmin && std::fabs(ex.t - ray.tmin) <= 1e-9 * std::fabs(ex.t)) ||
                     (at_tmax && std::fabs(ex.t - ray.tmax) <= 1e-9 * std::fabs(ex.t));
  if (on_boundary)
    out.right = RightSide::Both;
  else
    out.right = claim_holds == model_reported ? RightSide::Model : RightSide::Embree;
  return out;
}

uint32_t Arbiter::find_candidate(const Ray& ray) const {
  Hit closest = triangles_.flat(embree_.intersect(ray));
  if (closest.hit()) return closest.prim;
  // Embree's occlusion query saw something its closest-hit query did not: search all.
  for (uint32_t p = 0; p < triangles_.count(); ++p) {
    ExactHit ex = exact(p, ray);
    double slack = t_slack(ray, ex.t) + config_.range_epsilon * std::fabs(ex.t);
    if ((ex.inside || ex.near_edge(config_.edge_epsilon)) && (ex.opaque || ex.alpha_edge) &&
        ex.t >= ray.tmin - slack && ex.t <= ray.tmax + slack)
      return p;
  }
  return kNoHit;
}

Verdict Arbiter::judge(const Ray& ray, const Hit& embree, uint32_t model_prim,
                       float model_t) const {
  bool model_hit = model_prim != kNoHit, embree_hit = embree.hit();
  if (!model_hit && !embree_hit) return {};
  constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  if (ray.query == Query::AnyHit) {
    if (model_hit && embree_hit) return {};
    if (model_hit) return classify(ray, model_prim, true, kNone);
    uint32_t candidate = find_candidate(ray);
    if (candidate == kNoHit) return {false, MismatchClass::Unexplained, RightSide::Model, kNoHit};
    return classify(ray, candidate, false, kNone);
  }
  if (model_hit && embree_hit) {
    bool same_distance = same_t(model_t, embree.t, ray, config_.t_tolerance);
    if (same_distance && model_prim == embree.prim) return {};
    if (same_distance) {
      // Two triangles at one distance: through their shared edge, a tie, or one is not hit.
      ExactHit a = exact(model_prim, ray);
      ExactHit b = exact(embree.prim, ray);
      bool a_edge = a.near_edge(config_.edge_epsilon);
      bool b_edge = b.near_edge(config_.edge_epsilon);
      if (a_edge && b_edge)
        return {false, MismatchClass::EdgeOrVertex, RightSide::Both, model_prim};
      if ((a.inside || a_edge) && (b.inside || b_edge))
        return {false, MismatchClass::EqualTTie, RightSide::Both, model_prim};
      if (!(a.inside || a_edge)) return classify(ray, model_prim, true, kNone);
      return classify(ray, embree.prim, false, kNone);
    }
    if (model_prim == embree.prim) {
      // One triangle, two distances: only ill-conditioning excuses that. fp32 t errs by about
      // the coordinates' ulps over the cosine of the angle to the plane.
      Verdict v = classify(ray, model_prim, true, kNone);
      ExactHit ex = exact(model_prim, ray);
      double conditioned = t_slack(ray, ex.t) / std::max(ex.cosine, 1e-12);
      bool ill_conditioned = std::fabs(double(model_t) - embree.t) <= conditioned;
      if (v.cls != MismatchClass::Degenerate && v.cls != MismatchClass::Grazing)
        v.cls = ill_conditioned ? MismatchClass::Grazing : MismatchClass::Unexplained;
      v.right = std::fabs(model_t - ex.t) <= std::fabs(embree.t - ex.t) ? RightSide::Model
                                                                        : RightSide::Embree;
      return v;
    }
    // Different distances: the side with the nearer hit claims the other missed it.
    if (model_t < embree.t) return classify(ray, model_prim, true, embree.t);
    return classify(ray, embree.prim, false, model_t);
  }
  if (model_hit) return classify(ray, model_prim, true, kNone);
  return classify(ray, embree.prim, false, kNone);
}

}  // namespace rtsim
