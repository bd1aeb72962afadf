#include "workloads/pipeline/surfels.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>

#include "workloads/pipeline/rng.h"
#include "workloads/pipeline/sampling.h"

namespace rtsim::pipeline {
namespace {

uint64_t cell_key(int64_t x, int64_t y, int64_t z) {
  auto f = [](int64_t v) { return uint64_t(v + (1 << 20)) & 0x1fffff; };
  return (f(x) << 42) | (f(y) << 21) | f(z);
}

}  // namespace

template <typename F>
void SurfelCache::for_each_near(const glm::vec3& p, float reach, F&& f) const {
  float cell = 2.0f * radius_;
  glm::vec3 lo = glm::floor((p - reach) / cell), hi = glm::floor((p + reach) / cell);
  for (auto x = int64_t(lo.x); x <= int64_t(hi.x); ++x)
    for (auto y = int64_t(lo.y); y <= int64_t(hi.y); ++y)
      for (auto z = int64_t(lo.z); z <= int64_t(hi.z); ++z) {
        auto found = cells_.find(cell_key(x, y, z));
        if (found == cells_.end()) continue;
        for (uint32_t i : found->second) f(surfels_[i]);
      }
}

void SurfelCache::set_radius(float radius) {
  if (!surfels_.empty()) throw std::logic_error("SurfelCache: radius set after surfels");
  radius_ = radius;
}

void SurfelCache::add(const Surfel& s) {
  glm::vec3 c = glm::floor(s.position / (2.0f * radius_));
  cells_[cell_key(int64_t(c.x), int64_t(c.y), int64_t(c.z))].push_back(uint32_t(surfels_.size()));
  surfels_.push_back(s);
}

float SurfelCache::distance(const Surfel& s, const glm::vec3& p) const {
  glm::vec3 d = p - s.position;
  float along = glm::dot(d, s.normal);
  glm::vec3 across = d - along * s.normal;
  return std::sqrt(glm::dot(across, across) + 16.0f * along * along) / radius_;
}

float SurfelCache::weight(const Surfel& s, const glm::vec3& p, const glm::vec3& n) const {
  float dist = distance(s, p);
  if (dist >= 1.0f) return 0.0f;
  float x = 1.0f - dist;
  float falloff = x * x * (3.0f - 2.0f * x);
  float cos = std::max(0.0f, glm::dot(n, s.normal));
  return falloff * cos * cos;
}

float SurfelCache::coverage(const glm::vec3& p, const glm::vec3& n) const {
  float sum = 0.0f;
  for_each_near(p, radius_, [&](const Surfel& s) { sum += weight(s, p, n); });
  return sum;
}

bool SurfelCache::gaussian_mean(const glm::vec3& p, const glm::vec3& n, float reach, float sigma,
                                bool by_samples, glm::vec3& out) const {
  float inv_two_sigma2 = 1.0f / (2.0f * sigma * sigma);
  float wsum = 0.0f;
  glm::vec3 sum(0.0f);
  for_each_near(p, reach * radius_, [&](const Surfel& s) {
    if (s.irradiance_samples == 0) return;
    float dist = distance(s, p);
    float cos = glm::dot(n, s.normal);
    if (dist >= reach || cos <= 0.0f) return;
    float w = std::exp(-dist * dist * inv_two_sigma2) * cos * cos;
    if (by_samples) w *= float(s.irradiance_samples);
    wsum += w;
    sum += w * s.irradiance_sum / float(s.irradiance_samples);
  });
  if (wsum <= 0.0f) return false;
  out = sum / wsum;
  return true;
}

bool SurfelCache::irradiance(const glm::vec3& p, const glm::vec3& n, glm::vec3& out) const {
  return gaussian_mean(p, n, 2.0f, 0.5f, false, out);
}

void SurfelCache::smooth_irradiance(float reach) {
  std::vector<glm::vec3> mean(surfels_.size(), glm::vec3(0.0f));
  std::vector<bool> found(surfels_.size(), false);
  for (size_t i = 0; i < surfels_.size(); ++i)
    found[i] =
        gaussian_mean(surfels_[i].position, surfels_[i].normal, reach, reach / 2, true, mean[i]);
  for (size_t i = 0; i < surfels_.size(); ++i) {
    if (!found[i]) continue;
    surfels_[i].irradiance_sum = mean[i];
    surfels_[i].irradiance_samples = 1;
  }
}

uint32_t spawn_surfels(const FrameContext& ctx, const GBuffer& g, SurfelCache& cache) {
  const GiSpec& spec = ctx.passes.gi;
  std::vector<int64_t> first = g.first_sample_of_pixel();
  uint32_t tiles_x = (g.width + spec.tile - 1) / spec.tile;
  uint32_t tiles_y = (g.height + spec.tile - 1) / spec.tile;
  float surfel_area = kPi * cache.radius() * cache.radius();
  float pixel_angle = ctx.camera.pixel_angle();
  uint32_t stride = std::min(spec.coverage_stride, spec.tile);
  if (cache.radius() <= 0.0f) {
    std::vector<float> depths;
    for (const GSample& s : g.samples)
      if (s.surface.hit()) depths.push_back(s.depth);
    if (depths.empty()) return 0;
    std::nth_element(depths.begin(), depths.begin() + long(depths.size() / 2), depths.end());
    float median = depths[depths.size() / 2];
    cache.set_radius(
        std::max(0.75f * float(spec.tile) * pixel_angle * median, 1e-6f * ctx.scene.diagonal));
  }
  uint32_t spawned = 0;
  for (uint32_t ty = 0; ty < tiles_y; ++ty)
    for (uint32_t tx = 0; tx < tiles_x; ++tx) {
      int64_t best = -1;
      float best_coverage = 0.0f;
      for (uint32_t y = ty * spec.tile + stride / 2; y < std::min(g.height, (ty + 1) * spec.tile);
           y += stride)
        for (uint32_t x = tx * spec.tile + stride / 2; x < std::min(g.width, (tx + 1) * spec.tile);
             x += stride) {
          int64_t i = first[size_t(y) * g.width + x];
          if (i < 0 || !g.samples[size_t(i)].surface.hit()) continue;
          const Surface& s = g.samples[size_t(i)].surface;
          float c = cache.coverage(s.position, s.normal);
          if (best < 0 || c < best_coverage) {
            best = i;
            best_coverage = c;
          }
        }
      if (best < 0 || best_coverage >= spec.coverage_threshold) continue;
      if (cache.surfels().size() >= spec.max_surfels) return spawned;
      const GSample& s = g.samples[size_t(best)];
      float cos = std::max(0.1f, glm::dot(s.surface.normal, -s.view));
      float pixel_size = s.depth * pixel_angle;
      float tile_area = float(spec.tile * spec.tile) * pixel_size * pixel_size / cos;
      Pcg32 rng = make_rng(ctx.seed, RngStream::SurfelSpawn, ctx.frame, ty * tiles_x + tx);
      if (rng.uniform() >= std::min(1.0f, tile_area / surfel_area)) continue;
      Surfel surfel;
      surfel.position = s.surface.position;
      surfel.normal = s.surface.normal;
      surfel.prim = s.surface.prim;
      surfel.pixel = s.pixel;
      surfel.born_frame = ctx.frame;
      cache.add(surfel);
      ++spawned;
    }
  return spawned;
}

std::vector<uint32_t> gi_ray_counts(const std::vector<Surfel>& surfels, const GiSpec& spec,
                                    uint32_t frame) {
  std::vector<uint32_t> counts(surfels.size(), 0);
  if (surfels.empty() || spec.budget == 0) return counts;
  std::vector<double> wanted(surfels.size());
  double total = 0.0;
  for (size_t i = 0; i < surfels.size(); ++i) {
    bool young = frame - surfels[i].born_frame < spec.new_surfel_frames;
    wanted[i] = std::floor(double(spec.rays_per_surfel) * (young ? spec.new_surfel_boost : 1.0));
    total += wanted[i];
  }
  double scale = total > double(spec.budget) ? double(spec.budget) / total : 1.0;
  uint64_t given = 0;
  for (size_t i = 0; i < surfels.size(); ++i) {
    counts[i] = uint32_t(std::floor(wanted[i] * scale));
    given += counts[i];
  }
  if (scale < 1.0) {
    size_t start = (size_t(frame) * 7919u) % surfels.size();
    for (size_t k = 0; given < spec.budget; ++k, ++given) counts[(start + k) % surfels.size()]++;
  }
  return counts;
}

}  // namespace rtsim::pipeline
