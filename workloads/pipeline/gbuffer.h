// The G-buffer that the camera pass fills: one entry per camera sample with the closest hit's
// position, normal, material and depth. Later passes pick the samples they shoot from.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "workloads/pipeline/context.h"

namespace rtsim::pipeline {

struct GSample {
  float sx = 0.0f, sy = 0.0f;  // screen position, pixels
  uint32_t pixel = 0;
  uint16_t index = 0;    // sample index within the pixel
  float depth = 0.0f;    // distance along the camera ray; 0 if nothing was hit
  glm::vec3 view{0.0f};  // unit camera ray direction
  Surface surface;
  uint32_t material = 0;  // index into MaterialTable::materials (if hit)
};

struct GBuffer {
  uint32_t width = 0, height = 0;
  std::vector<GSample> samples;

  // The samples a pass at resolution_scale shoots from: every sample at scale 1; otherwise the
  // image is cut into cells of 1/scale pixels and one sample per cell is chosen, rotating with
  // the frame (as Pica Pica's half-resolution passes do), cells in row-major order.
  std::vector<uint32_t> select(float resolution_scale, uint32_t frame) const;
  // Cells of the grid at resolution_scale (the most samples select() returns).
  static uint64_t cell_count(uint32_t width, uint32_t height, float resolution_scale);
  // The cell of the grid at resolution_scale that pixel lies in (the pixel itself at scale 1).
  static uint32_t cell_of(uint32_t pixel, uint32_t width, uint32_t height, float resolution_scale);
  // The first sample of every pixel, or -1 where a pixel has none.
  std::vector<int64_t> first_sample_of_pixel() const;
};

}  // namespace rtsim::pipeline
