// Helpers shared by the ray-stream tests: temp paths, sample rays, raw file access.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "traces/stream.h"

namespace rtsim::test {

inline std::string temp_path(const std::string& name) {
  return "/tmp/rtsim-test-" + std::to_string(getpid()) + "-" + name;
}

// n rays cycling through every ray type and query, a third forced opaque, with awkward values
// (-0, +inf, denormals).
inline std::vector<Ray> sample_rays(size_t n) {
  std::vector<Ray> rays(n);
  for (size_t i = 0; i < n; ++i) {
    Ray& r = rays[i];
    r.org = {float(i) * 0.5f, -float(i), 1e7f - float(i)};
    r.dir = {i % 3 == 0 ? -0.0f : 1.0f, i % 5 == 0 ? 1e-40f : -0.25f, 0.75f};
    r.tmin = float(i % 4) * 1e-4f;
    r.tmax = i % 2 ? std::numeric_limits<float>::infinity() : 100.0f + float(i);
    r.type = static_cast<RayType>(i % kRayTypeCount);
    r.query = static_cast<Query>((i / kRayTypeCount) % 2);
    r.force_opaque = i % 3 == 1;
    r.sample = uint16_t(i * 7);
    r.pixel = uint32_t(i * 13 % 2048);  // within sample_header's grid and frames
    r.frame = uint32_t(i / 100 % 3);
  }
  return rays;
}

inline StreamHeader sample_header(uint32_t chunk_rays = 64) {
  StreamHeader h;
  h.scene_source = "builtin:cornell";
  h.scene_fingerprint = 0x0123456789abcdefull;
  h.workload = "test";
  h.generator = "rtsim-test";
  h.seed = 42;
  h.frame_count = 3;
  h.width = 64;
  h.height = 32;
  h.chunk_rays = chunk_rays;
  return h;
}

inline void write_stream(const std::string& path, const std::vector<Ray>& rays,
                         uint32_t chunk_rays = 64) {
  RayStreamWriter writer(path, sample_header(chunk_rays));
  for (const Ray& r : rays) writer.write(r);
  writer.finish();
}

inline std::vector<uint8_t> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_bytes(const std::string& path, const std::vector<uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

}  // namespace rtsim::test
