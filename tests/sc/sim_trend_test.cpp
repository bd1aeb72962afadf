// The Aila & Karras (HPG 2010) study of model/sched/README.md on a small machine: treelet queues
// cut the DRAM traffic of diffuse rays only while their ray states cost nothing. Held in an SRAM,
// the states' bytes as extra L2 serve depth-first traversal better; spilled to memory, the
// states move more bytes than the queues save, and the run slows down. (scripts/treelet-study
// prints the Conference, Sponza and Sibenik figures.)
#include <gtest/gtest.h>

#include "tests/sc/sim_test_util.h"

namespace rtsim {
namespace {

struct Design {
  double dram_bytes_per_ray, cycles;
};

Design run(const HwConfig& config, const test::SimScene& s, const std::vector<Ray>& rays) {
  nlohmann::json doc = test::simulate(config, s.scene, rays);
  return {doc["ray_types"]["diffuse_gi"]["dram_bytes_per_ray"].get<double>(),
          test::stat(doc, "cycles")};
}

TEST(SimTrend, TreeletQueuesWinOnlyWhileTheirRayStatesAreFree) {
  test::SimScene s("pica");
  std::vector<Ray> rays = sample_diffuse_rays(s.scene.mesh, 20000, 21);
  HwConfig depth_first = test::small_machine();
  depth_first.rt_units = 4;
  depth_first.treelet_queues.max_rays = 4096;
  depth_first.bvh.treelet_bytes = 4096;
  HwConfig free_state = depth_first;
  free_state.rt.mode = TraversalMode::Treelet;
  HwConfig held = free_state;  // an SRAM of half the L2's size, ported, holding rays back
  RayBufferConfig& buffer = held.treelet_queues.buffer;
  buffer.bytes = last_level(held).cache.size_bytes / 2;
  buffer.banks = 2;
  buffer.bytes_per_cycle = 32;
  buffer.latency = 4;
  held.bvh.treelet_budget = TreeletBudget::NodesAndTriangles;
  HwConfig spilled = held;
  spilled.treelet_queues.buffer.overflow = RayBufferOverflow::Spill;
  HwConfig equal_sram = depth_first;
  last_level(equal_sram).cache.size_bytes += buffer.bytes;
  equal_sram.bvh.treelet_budget = TreeletBudget::NodesAndTriangles;

  Design base = run(depth_first, s, rays), free_queues = run(free_state, s, rays);
  Design hold = run(held, s, rays), spill = run(spilled, s, rays);
  Design twin = run(equal_sram, s, rays);
  EXPECT_LT(free_queues.dram_bytes_per_ray, 0.8 * base.dram_bytes_per_ray)
      << "free states: the queues cut DRAM bytes per ray against the same caches";
  EXPECT_LT(twin.dram_bytes_per_ray, hold.dram_bytes_per_ray)
      << "the ray buffer's SRAM as L2 serves depth-first better than the held queues";
  EXPECT_GT(spill.dram_bytes_per_ray, base.dram_bytes_per_ray)
      << "spilled states move more bytes than the queues save";
  EXPECT_GT(spill.cycles, hold.cycles) << "and spilling is slower than holding rays back";
}

}  // namespace
}  // namespace rtsim
