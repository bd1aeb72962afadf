#include "workloads/pipeline/preview_filter.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace rtsim::pipeline {
namespace {

bool same_surface(const GSample& a, const GSample& b) {
  if (!a.surface.hit() || !b.surface.hit()) return false;
  return glm::dot(a.surface.normal, b.surface.normal) > 0.9f &&
         std::abs(a.depth - b.depth) <= 0.05f * a.depth;
}

}  // namespace

std::vector<float> filter_on_surfaces(const GBuffer& g, const std::vector<float>& values,
                                      size_t channels, int radius, int stride) {
  std::vector<float> out = values;
  std::vector<int64_t> first = g.first_sample_of_pixel();
  auto w = int64_t(g.width), h = int64_t(g.height);
  std::vector<float> sum(channels);
  std::vector<uint32_t> count(channels);
  for (size_t i = 0; i < g.samples.size(); ++i) {
    const GSample& s = g.samples[i];
    if (!s.surface.hit()) continue;
    std::fill(sum.begin(), sum.end(), 0.0f);
    std::fill(count.begin(), count.end(), 0u);
    auto add = [&](size_t j) {
      for (size_t c = 0; c < channels; ++c) {
        float v = values[j * channels + c];
        if (v < 0.0f) continue;
        sum[c] += v;
        count[c]++;
      }
    };
    add(i);
    int64_t x0 = s.pixel % g.width, y0 = s.pixel / g.width;
    for (int64_t dy = -radius; dy <= radius; dy += stride)
      for (int64_t dx = -radius; dx <= radius; dx += stride) {
        int64_t x = x0 + dx, y = y0 + dy;
        if (x < 0 || y < 0 || x >= w || y >= h) continue;
        int64_t j = first[size_t(y * w + x)];
        if (j >= 0 && size_t(j) != i && same_surface(s, g.samples[size_t(j)])) add(size_t(j));
      }
    for (size_t c = 0; c < channels; ++c)
      if (values[i * channels + c] >= 0.0f && count[c] > 0)
        out[i * channels + c] = sum[c] / float(count[c]);
  }
  return out;
}

}  // namespace rtsim::pipeline
