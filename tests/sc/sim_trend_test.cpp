// The trend of Aila & Karras (HPG 2010) on a small built-in scene: with treelet queues, DRAM
// traffic of diffuse rays falls clearly below per-ray depth-first traversal at equal cache
// sizes. (The Conference figures are in model/SIM.md.)
#include <gtest/gtest.h>

#include "tests/sc/sim_test_util.h"

namespace rtsim {
namespace {

TEST(SimTrend, TreeletQueuesCutDramTrafficOfDiffuseRays) {
  test::SimScene s("pica");
  std::vector<Ray> rays = sample_diffuse_rays(s.scene.mesh, 20000, 21);
  HwConfig config = test::small_machine();
  config.rt_units = 4;
  config.treelet_queues.max_rays = 4096;
  config.bvh.treelet_bytes = 4096;
  nlohmann::json baseline = test::simulate(config, s.scene, rays);
  config.rt.mode = TraversalMode::Treelet;
  nlohmann::json treelet = test::simulate(config, s.scene, rays);
  double base = baseline["ray_types"]["diffuse_gi"]["dram_bytes_per_ray"].get<double>();
  double queued = treelet["ray_types"]["diffuse_gi"]["dram_bytes_per_ray"].get<double>();
  EXPECT_LT(queued, 0.8 * base) << "DRAM bytes per ray: depth-first " << base << ", treelet "
                                << queued;
  EXPECT_GT(treelet["coherence"]["rays_per_treelet_visit"].get<double>(), 2.0);
  EXPECT_EQ(baseline["stats"]["counters"]["l2.accesses"] > 0, true);
}

}  // namespace
}  // namespace rtsim
