// Whole simulations on a built-in scene: every ray retires with Embree's answer, the stats
// add up, the run is deterministic, and temporal decoupling moves the cycle count only a
// little.
#include <gtest/gtest.h>

#include "tests/sc/sim_test_util.h"

namespace rtsim {
namespace {

class SimRun : public ::testing::TestWithParam<const char*> {};

TEST_P(SimRun, EveryRayRetiresWithEmbreesAnswer) {
  test::SimScene s;
  std::vector<Ray> rays = test::mixed_rays(s.scene, 2000, 3);
  HwConfig config = test::small_machine();
  std::string mode = GetParam();
  config.rt.mode = mode == "treelet"  ? TraversalMode::Treelet
                   : mode == "packet" ? TraversalMode::Packet
                                      : TraversalMode::DepthFirst;
  nlohmann::json doc = test::simulate(config, s.scene, rays, true);
  EXPECT_EQ(doc["summary"]["rays"], rays.size());
  EXPECT_EQ(doc["verify"]["rays"], rays.size());
  EXPECT_EQ(doc["verify"]["unexplained"], 0) << doc["verify"].dump();
  EXPECT_EQ(test::stat(doc, "dispatch.rays"), double(rays.size()));
  EXPECT_EQ(test::stat(doc, "rt0.rays") + test::stat(doc, "rt1.rays"), double(rays.size()));
  double typed = 0;
  for (auto& [name, t] : doc["ray_types"].items()) typed += t["rays"].get<double>();
  EXPECT_EQ(typed, double(rays.size())) << "per-type counts add up";
  // DRAM never exceeds its bandwidth: its bus was busy at most every cycle.
  EXPECT_LE(test::stat(doc, "dram.bytes") / 16.0, test::stat(doc, "cycles") + 1);
  EXPECT_GT(doc["summary"]["rays_per_cycle"].get<double>(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Modes, SimRun, ::testing::Values("depth_first", "treelet", "packet"));

TEST(SimDeterminism, SameInputsGiveIdenticalStats) {
  test::SimScene s;
  std::vector<Ray> rays = test::mixed_rays(s.scene, 1500, 9);
  HwConfig config = test::small_machine();
  config.rt.mode = TraversalMode::Treelet;
  first_level(config).cache.replacement = "random";  // seeded
  nlohmann::json a = test::simulate(config, s.scene, rays);
  nlohmann::json b = test::simulate(config, s.scene, rays);
  EXPECT_EQ(a.dump(), b.dump());
}

TEST(SimQuantum, DecouplingChangesCyclesOnlySlightly) {
  test::SimScene s;
  std::vector<Ray> rays = test::mixed_rays(s.scene, 3000, 5);
  HwConfig config = test::small_machine();
  config.sim.quantum_cycles = 1;
  nlohmann::json exact = test::simulate(config, s.scene, rays);
  config.sim.quantum_cycles = 32;
  nlohmann::json fast = test::simulate(config, s.scene, rays);
  double c1 = exact["summary"]["cycles"].get<double>(),
         c32 = fast["summary"]["cycles"].get<double>();
  EXPECT_NEAR(c32 / c1, 1.0, 0.03) << "quantum 32 vs exact order";
  EXPECT_NEAR(test::stat(fast, "dram.bytes") / test::stat(exact, "dram.bytes"), 1.0, 0.03);
}

}  // namespace
}  // namespace rtsim
