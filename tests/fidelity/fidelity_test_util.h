// A small ray stream for the fidelity tests: diffuse-GI-like rays on a built-in scene, written
// once per test process to a temporary file.
#pragma once

#include <unistd.h>

#include <string>

#include "model/verify/ray_samples.h"
#include "traces/stream.h"
#include "workloads/scene.h"

namespace rtsim::test {

inline std::string small_stream(const std::string& scene_spec, size_t rays, uint64_t seed = 7) {
  std::string path =
      "/tmp/rtsim-fidelity-" + std::to_string(getpid()) + "-" + std::to_string(rays) + ".rays";
  Scene scene = load_scene(scene_spec);
  StreamHeader header;
  header.scene_source = scene.source;
  header.scene_fingerprint = scene.fingerprint;
  header.workload = "fidelity test";
  header.generator = "rtsim tests";
  header.seed = seed;
  header.chunk_rays = 1000;  // several chunks, so range reads cross chunk boundaries
  RayStreamWriter writer(path, header);
  for (const Ray& ray : sample_diffuse_rays(scene.triangles(), rays, seed)) writer.write(ray);
  writer.finish();
  return path;
}

}  // namespace rtsim::test
