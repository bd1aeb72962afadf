// World-space surfels for diffuse GI (Pica Pica): discs spawned from the G-buffer where the
// screen is least covered, kept across frames, looked up through a uniform grid. Placement
// follows the talk: per 16x16 tile, find the pixel with the lowest surfel coverage and, if it
// is below the threshold, spawn a surfel there with a chance proportional to the pixel's
// projected area (so surfel density is even in world space); repeated every frame, this fills
// holes iteratively. Coverage is evaluated on every coverage_stride-th pixel of a tile to keep
// the cost low.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <unordered_map>
#include <vector>

#include "workloads/pipeline/context.h"
#include "workloads/pipeline/gbuffer.h"

namespace rtsim::pipeline {

struct Surfel {
  glm::vec3 position{0.0f}, normal{0.0f, 1.0f, 0.0f};
  uint32_t prim = 0;   // triangle it lies on
  uint32_t pixel = 0;  // pixel it was spawned from (GI rays are tagged with it)
  uint32_t born_frame = 0;
  glm::vec3 irradiance_sum{0.0f};  // for the preview
  uint32_t irradiance_samples = 0;
};

class SurfelCache {
 public:
  // radius 0: set by the first spawn_surfels() call (see there).
  explicit SurfelCache(float radius) : radius_(radius) {}

  float radius() const { return radius_; }
  void set_radius(float radius);
  const std::vector<Surfel>& surfels() const { return surfels_; }
  std::vector<Surfel>& surfels() { return surfels_; }
  void add(const Surfel& s);

  // Sum of surfel weights at p: smoothstep falloff with a Mahalanobis distance that squashes
  // the disc along its normal, times the squared cosine between normals (after Lehtinen 2008).
  float coverage(const glm::vec3& p, const glm::vec3& n) const;
  // Mean irradiance of the surfels within two radii of p, weighted by a Gaussian of the same
  // distance and the squared cosine; false if none is near. Smoother than coverage, for
  // pictures.
  bool irradiance(const glm::vec3& p, const glm::vec3& n, glm::vec3& out) const;
  // Replaces each surfel's irradiance by the weighted mean over the surfels within `reach`
  // radii (Gaussian of sigma reach / 2, squared cosine): a denoise for pictures, where a
  // surfel has had only a few rays.
  void smooth_irradiance(float reach);

 private:
  template <typename F>
  void for_each_near(const glm::vec3& p, float reach, F&& f) const;
  // Distance from p in radii, squashed along the surfel's normal (Mahalanobis).
  float distance(const Surfel& s, const glm::vec3& p) const;
  float weight(const Surfel& s, const glm::vec3& p, const glm::vec3& n) const;
  // Mean irradiance of the surfels within `reach` radii of p, each weighted by a Gaussian
  // (sigma in radii) of its distance, the squared cosine between normals and, if by_samples,
  // its sample count; false if none is near.
  bool gaussian_mean(const glm::vec3& p, const glm::vec3& n, float reach, float sigma,
                     bool by_samples, glm::vec3& out) const;

  float radius_;
  std::vector<Surfel> surfels_;
  // Cells are 2r wide, so the surfels within r of a point lie in at most 2 cells per axis.
  std::unordered_map<uint64_t, std::vector<uint32_t>> cells_;
};

// Spawns at most one surfel per tile of this frame's G-buffer; returns how many it spawned.
// An unset radius becomes 3/4 of a tile's footprint at the median depth of this G-buffer, so
// one surfel covers about one tile there.
uint32_t spawn_surfels(const FrameContext& ctx, const GBuffer& g, SurfelCache& cache);

// GI rays per surfel this frame: rays_per_surfel, times new_surfel_boost for new surfels, all
// scaled down to fit the budget (remainders go one each to surfels in an order that rotates
// with the frame). The sum is min(budget, wanted).
std::vector<uint32_t> gi_ray_counts(const std::vector<Surfel>& surfels, const GiSpec& spec,
                                    uint32_t frame);

}  // namespace rtsim::pipeline
