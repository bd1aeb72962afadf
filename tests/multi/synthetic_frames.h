// Frames of irregular samples for the multi-device tests, without the pipeline: a pinhole
// camera over a width x height grid; each pixel shoots 1 + a blob of extra camera samples that
// moves right by `speed` pixels per frame (the irregular distribution of Harada & Fujita), and
// the samples in a second blob moving left each spawn `extra_rays` more rays (cost that the
// sample count does not see).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "traces/stream.h"
#include "tests/temp_dir.h"

namespace rtsim::test {

struct SyntheticFrames {
  uint32_t width = 64, height = 36, frames = 8;
  float speed = 1.5f;         // pixels per frame the blobs move
  uint32_t blob_samples = 4;  // extra camera samples at a blob's centre
  uint32_t extra_rays = 3;    // rays each sample in the second blob spawns
  glm::vec3 eye{0.0f, 2.4f, 9.0f}, look_at{0.0f, 0.9f, 0.0f};  // the pica room's camera
  float fov = 50.0f;
};

inline float blob(float x, float y, float cx, float cy, float sigma) {
  return std::exp(-((x - cx) * (x - cx) + (y - cy) * (y - cy)) / (2 * sigma * sigma));
}

inline std::vector<Ray> synthetic_frame(const SyntheticFrames& s, uint32_t frame) {
  glm::vec3 forward = glm::normalize(s.look_at - s.eye);
  glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
  glm::vec3 up = glm::cross(right, forward);
  float half = std::tan(s.fov * 0.5f * 3.14159265f / 180.0f);
  float aspect = float(s.width) / float(s.height), sigma = float(s.width) / 8;
  float hot_x = 0.25f * float(s.width) + s.speed * float(frame);
  float costly_x = 0.75f * float(s.width) - s.speed * float(frame);
  std::vector<Ray> rays;
  for (uint32_t y = 0; y < s.height; ++y)
    for (uint32_t x = 0; x < s.width; ++x) {
      float fx = float(x) + 0.5f, fy = float(y) + 0.5f, cy = 0.5f * float(s.height);
      auto samples = 1 + uint32_t(std::lround(s.blob_samples * blob(fx, fy, hot_x, cy, sigma)));
      bool costly = blob(fx, fy, costly_x, cy, sigma) > 0.5f;
      for (uint32_t k = 0; k < samples; ++k) {
        float jx = (float(k) + 0.5f) / float(samples);  // spread over the pixel
        float u = (2 * (float(x) + jx) / float(s.width) - 1) * half * aspect;
        float v = (1 - 2 * fy / float(s.height)) * half;
        Ray ray;
        ray.org = s.eye;
        ray.dir = glm::normalize(forward + u * right + v * up);
        ray.pixel = y * s.width + x;
        ray.frame = frame;
        ray.sample = uint16_t(k);
        rays.push_back(ray);
        for (uint32_t e = 0; costly && e < s.extra_rays; ++e) {
          Ray extra = ray;
          extra.type = RayType::Reflection;
          extra.dir = glm::normalize(ray.dir + glm::vec3(0.01f * float(e), 0.0f, 0.0f));
          rays.push_back(extra);
        }
      }
    }
  return rays;
}

inline std::string write_synthetic_stream(const std::string& name, const SyntheticFrames& s,
                                          const std::string& scene_source, uint64_t fingerprint,
                                          const std::vector<uint32_t>& empty_frames = {}) {
  std::string path = scratch_path(name + ".rays");
  StreamHeader h;
  h.scene_source = scene_source;
  h.scene_fingerprint = fingerprint;
  h.workload = name;
  h.frame_count = s.frames;
  h.width = s.width;
  h.height = s.height;
  RayStreamWriter writer(path, h);
  for (uint32_t f = 0; f < s.frames; ++f) {
    bool empty = false;
    for (uint32_t e : empty_frames) empty |= e == f;
    if (!empty)
      for (const Ray& ray : synthetic_frame(s, f)) writer.write(ray);
  }
  writer.finish();
  return path;
}

}  // namespace rtsim::test
