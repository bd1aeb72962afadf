#include "workloads/pipeline/gbuffer.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace rtsim::pipeline {
namespace {

uint32_t cells_along(uint32_t pixels, float scale) {
  return std::max<uint32_t>(1, uint32_t(std::ceil(double(pixels) * double(scale))));
}

}  // namespace

uint64_t GBuffer::cell_count(uint32_t width, uint32_t height, float scale) {
  if (scale >= 1.0f) return uint64_t(width) * height;
  return uint64_t(cells_along(width, scale)) * cells_along(height, scale);
}

uint32_t GBuffer::cell_of(uint32_t pixel, uint32_t width, uint32_t height, float scale) {
  if (scale >= 1.0f) return pixel;
  uint32_t cw = cells_along(width, scale), ch = cells_along(height, scale);
  uint32_t x = pixel % width, y = pixel / width;
  auto cx = std::min(cw - 1, uint32_t(double(x) * scale));
  auto cy = std::min(ch - 1, uint32_t(double(y) * scale));
  return cy * cw + cx;
}

std::vector<uint32_t> GBuffer::select(float scale, uint32_t frame) const {
  std::vector<uint32_t> out;
  if (scale >= 1.0f) {
    out.resize(samples.size());
    std::iota(out.begin(), out.end(), 0u);
    return out;
  }
  std::vector<uint32_t> cell(samples.size()), start(cell_count(width, height, scale) + 1, 0);
  for (size_t i = 0; i < samples.size(); ++i) {
    cell[i] = cell_of(samples[i].pixel, width, height, scale);
    start[cell[i] + 1]++;
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<uint32_t> next(start.begin(), start.end() - 1), order(samples.size());
  for (size_t i = 0; i < samples.size(); ++i) order[next[cell[i]]++] = uint32_t(i);
  for (size_t c = 0; c + 1 < start.size(); ++c) {
    uint32_t n = start[c + 1] - start[c];
    if (n > 0) out.push_back(order[start[c] + frame % n]);
  }
  return out;
}

std::vector<int64_t> GBuffer::first_sample_of_pixel() const {
  std::vector<int64_t> first(size_t(width) * height, -1);
  for (size_t i = samples.size(); i-- > 0;) first[samples[i].pixel] = int64_t(i);
  return first;
}

}  // namespace rtsim::pipeline
