// Whole simulations for tests: each runs in a forked child (SystemC allows one elaboration per
// process) and returns its stats document, so one test can compare several runs.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/config/hw_config.h"
#include "model/sc/fork_run.h"
#include "model/sc/sim_report.h"
#include "model/sched/sim_verifier.h"
#include "model/verify/ray_samples.h"
#include "traces/embree_scene.h"
#include "workloads/scene.h"

namespace rtsim::test {

// A small machine: 2 RT units of 2 warps x 8 rays, small caches.
inline HwConfig small_machine() {
  HwConfig c;
  c.rt_units = 2;
  c.rt.warps = 2;
  c.rt.warp_size = 8;
  first_level(c).cache = {4096, 64, 4, "lru", 4, 8};
  last_level(c).cache = {32768, 64, 8, "lru", 20, 32};
  c.dram = {16.0, 100, 32};
  c.treelet_queues.max_rays = 512;
  c.treelet_queues.min_batch = 8;
  c.bvh.width = 4;
  c.bvh.treelet_bytes = 1024;
  return c;
}

struct SimScene {
  explicit SimScene(const std::string& spec = "pica") : scene(load_scene(spec)) {}
  Scene scene;
};

// Runs one simulation in a child; returns its stats document without the "host" part.
// verify: check every ray against Embree (built in the child).
inline nlohmann::json simulate(const HwConfig& config, const Scene& scene,
                               const std::vector<Ray>& rays, bool verify = false,
                               uint32_t width = 0, uint32_t height = 0) {
  std::string text = run_in_child([&] {
    InstancedMesh instances = scene.instanced;
    TwoLevelBvh bvh = build_scene_levels(scene.mesh, instances, config.bvh);
    std::unique_ptr<TraversalUnit> model;
    std::unique_ptr<SimVerifier> verifier;
    if (verify) {
      model = std::make_unique<TraversalUnit>(bvh);
      verifier = std::make_unique<SimVerifier>(make_verifier(*model, scene.mesh, instances));
    }
    VectorRaySource source(rays);
    RtSimulator sim(config, bvh, source, width, height, verifier.get());
    sim.run();
    StatsRegistry stats;
    sim.report(stats);
    SimRunInfo info;
    info.bvh = bvh;
    info.verify = verifier ? &verifier->report() : nullptr;
    nlohmann::ordered_json doc = sim_stats_json(sim, stats, info);
    doc.erase("host");
    return doc.dump();
  });
  return nlohmann::json::parse(text);
}

// A counter or derived stat of a stats document by its registry name.
inline double stat(const nlohmann::json& doc, const std::string& name) {
  const nlohmann::json& stats = doc["stats"];
  return stats["counters"].contains(name) ? stats["counters"][name].get<double>()
                                          : stats["derived"][name].get<double>();
}

// Camera and diffuse rays of a scene, seeded.
inline std::vector<Ray> mixed_rays(const Scene& scene, size_t diffuse, uint64_t seed) {
  std::vector<Ray> rays = sample_camera_rays(scene.triangles(), 32, 24);
  std::vector<Ray> more = sample_diffuse_rays(scene.triangles(), diffuse, seed);
  rays.insert(rays.end(), more.begin(), more.end());
  for (size_t i = 0; i < rays.size(); i += 5) rays[i].query = Query::AnyHit;
  return rays;
}

}  // namespace rtsim::test
