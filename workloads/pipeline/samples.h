// Where camera samples go on the screen. Regular: one per pixel (with the frame's TAA jitter).
// Importance: "Ray Tracing Irregularly Distributed Samples on Multiple GPUs" (Harada & Fujita,
// 2014) lets a ray tracer place samples freely; here a per-pixel importance map (edges and the
// previous frame's ray cost) sets how many samples each pixel gets, by systematic sampling of
// its cumulative distribution, so the total is exact.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

#include "workloads/pipeline/spec.h"

namespace rtsim::pipeline {

struct SamplePosition {
  float sx = 0.0f, sy = 0.0f;  // screen position, pixels; pixel (x, y) spans [x, x + 1)
  uint32_t pixel = 0;
  uint16_t index = 0;  // sample index within the pixel
};

// The sub-pixel jitter of frame `frame` (Halton 2, 3), in [-0.5, 0.5)^2; zero if disabled.
glm::vec2 frame_jitter(uint32_t frame, bool enabled);

std::vector<SamplePosition> regular_samples(uint32_t width, uint32_t height, glm::vec2 jitter);

// count samples distributed by importance (one value >= 0 per pixel) mixed with a uniform
// share; positions within a pixel are random, seeded by (seed, frame, pixel).
std::vector<SamplePosition> importance_samples(uint32_t width, uint32_t height, uint64_t count,
                                               const std::vector<float>& importance,
                                               float uniform_share, uint64_t seed, uint32_t frame);

struct GBuffer;

// Importance per pixel from a G-buffer (depth, normal, material discontinuities) and the rays
// each pixel cost (all passes, previous frame); each part normalised to mean 1.
std::vector<float> importance_map(const GBuffer& gbuffer, const std::vector<uint32_t>& cost,
                                  const SampleSpec& spec);

}  // namespace rtsim::pipeline
