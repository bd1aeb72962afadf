#include "workloads/pipeline/samples.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "workloads/pipeline/gbuffer.h"
#include "workloads/pipeline/rng.h"
#include "workloads/pipeline/sampling.h"

namespace rtsim::pipeline {
namespace {

void normalise_to_mean_one(std::vector<float>& v) {
  double sum = 0.0;
  for (float x : v) sum += x;
  if (sum <= 0.0) return;
  auto scale = float(double(v.size()) / sum);
  for (float& x : v) x *= scale;
}

// 1 where a pixel differs from its right or lower neighbour in hit, material, normal or depth.
std::vector<float> edge_map(const GBuffer& g) {
  std::vector<int64_t> first = g.first_sample_of_pixel();
  std::vector<float> edges(first.size(), 0.0f);
  auto differs = [&](int64_t a, int64_t b) {
    if (a < 0 || b < 0) return false;
    const GSample& s = g.samples[size_t(a)];
    const GSample& t = g.samples[size_t(b)];
    if (s.surface.hit() != t.surface.hit()) return true;
    if (!s.surface.hit()) return false;
    if (s.material != t.material) return true;
    if (glm::dot(s.surface.normal, t.surface.normal) < 0.9f) return true;
    return std::abs(s.depth - t.depth) > 0.05f * std::min(s.depth, t.depth);
  };
  for (uint32_t y = 0; y < g.height; ++y)
    for (uint32_t x = 0; x < g.width; ++x) {
      size_t p = size_t(y) * g.width + x;
      bool right = x + 1 < g.width && differs(first[p], first[p + 1]);
      bool down = y + 1 < g.height && differs(first[p], first[p + g.width]);
      if (right) edges[p] = edges[p + 1] = 1.0f;
      if (down) edges[p] = edges[p + g.width] = 1.0f;
    }
  return edges;
}

}  // namespace

glm::vec2 frame_jitter(uint32_t frame, bool enabled) {
  if (!enabled) return glm::vec2(0.0f);
  return glm::vec2(halton(frame + 1, 2), halton(frame + 1, 3)) - glm::vec2(0.5f);
}

std::vector<SamplePosition> regular_samples(uint32_t width, uint32_t height, glm::vec2 jitter) {
  std::vector<SamplePosition> out(size_t(width) * height);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      SamplePosition& s = out[size_t(y) * width + x];
      s.sx = float(x) + 0.5f + jitter.x;
      s.sy = float(y) + 0.5f + jitter.y;
      s.pixel = y * width + x;
    }
  return out;
}

std::vector<SamplePosition> importance_samples(uint32_t width, uint32_t height, uint64_t count,
                                               const std::vector<float>& importance,
                                               float uniform_share, uint64_t seed, uint32_t frame) {
  size_t pixels = size_t(width) * height;
  double total = 0.0;
  for (size_t p = 0; p < pixels; ++p) total += importance[p];
  double uniform = total > 0.0 ? uniform_share : 1.0;
  std::vector<SamplePosition> out;
  out.reserve(count);
  // Systematic sampling: pixel p gets floor(C_p + o) - floor(C_{p-1} + o) samples, C the
  // cumulative expected count and o one random offset, so the counts sum to exactly `count`.
  Pcg32 rng = make_rng(seed, RngStream::SamplePlacement, frame, 0);
  double offset = rng.uniform(), cumulative = 0.0;
  auto before = uint64_t(std::floor(offset));
  for (size_t p = 0; p < pixels; ++p) {
    double share = uniform / double(pixels);
    if (total > 0.0) share += (1.0 - uniform) * importance[p] / total;
    cumulative += double(count) * share;
    auto upto = std::min<uint64_t>(count, uint64_t(std::floor(cumulative + offset)));
    if (p + 1 == pixels) upto = count;
    uint64_t n = std::min<uint64_t>(upto - std::min(upto, before), 65535);
    Pcg32 pixel_rng = make_rng(seed, RngStream::SamplePlacement, frame, p + 1);
    for (uint64_t i = 0; i < n; ++i) {
      SamplePosition s;
      s.sx = float(p % width) + pixel_rng.uniform();
      s.sy = float(p / width) + pixel_rng.uniform();
      s.pixel = uint32_t(p);
      s.index = uint16_t(i);
      out.push_back(s);
    }
    before = std::max(before, upto);
  }
  return out;
}

std::vector<float> importance_map(const GBuffer& gbuffer, const std::vector<uint32_t>& cost,
                                  const SampleSpec& spec) {
  size_t pixels = size_t(gbuffer.width) * gbuffer.height;
  std::vector<float> importance(pixels, 0.0f);
  if (spec.edges) {
    std::vector<float> edges = edge_map(gbuffer);
    normalise_to_mean_one(edges);
    for (size_t p = 0; p < pixels; ++p) importance[p] += edges[p];
  }
  if (spec.cost && cost.size() == pixels) {
    std::vector<float> c(cost.begin(), cost.end());
    normalise_to_mean_one(c);
    for (size_t p = 0; p < pixels; ++p) importance[p] += c[p];
  }
  return importance;
}

}  // namespace rtsim::pipeline
