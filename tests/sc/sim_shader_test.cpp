// Whole simulations with the shader side on (model/sched/shader_core.h): every ray still
// retires with Embree's answer, shading reads reach the L2 and DRAM at the configured bytes per
// hit, shading time shows in the cycles, and with `shader.model = "none"` nothing changes.
#include <gtest/gtest.h>

#include "tests/sc/sim_test_util.h"

namespace rtsim {
namespace {

HwConfig machine(const char* mode, std::vector<std::string> sets) {
  HwConfig c = test::small_machine();
  sets.push_back(std::string("rt.mode=\"") + mode + "\"");
  HwConfig loaded = load_hw_config("", sets);
  loaded.rt_units = c.rt_units;
  loaded.rt.warps = c.rt.warps;
  loaded.rt.warp_size = c.rt.warp_size;
  first_level(loaded).cache = first_level(c).cache;
  last_level(loaded).cache = last_level(c).cache;
  loaded.bvh = c.bvh;
  return loaded;
}

class SimShader : public ::testing::TestWithParam<const char*> {};

TEST_P(SimShader, ShadingCostsCyclesAndReadsWithoutChangingAnswers) {
  test::SimScene s("cornell");
  std::vector<Ray> rays = test::mixed_rays(s.scene, 600, 5);
  nlohmann::json off = test::simulate(machine(GetParam(), {}), s.scene, rays, true);
  nlohmann::json on = test::simulate(
      machine(GetParam(), {"shader.model=\"simt\"", "shader.warps=3", "shader.bytes_per_hit=96"}),
      s.scene, rays, true);
  EXPECT_EQ(on["verify"]["rays"], rays.size());
  EXPECT_EQ(on["verify"]["unexplained"], 0) << on["verify"].dump();
  EXPECT_FALSE(off["stats"]["counters"].contains("shader.busy_cycles"));
  EXPECT_TRUE(off["shader"].is_null());
  double hits = 0;
  for (const auto& [name, type] : on["ray_types"].items()) hits += type["hits"].get<double>();
  EXPECT_EQ(test::stat(on, "shader.rays"), rays.size());
  EXPECT_EQ(test::stat(on, "shader.hits"), hits);
  EXPECT_EQ(test::stat(on, "shader.read_bytes"), 96 * hits);
  EXPECT_GE(test::stat(on, "shader.reads.mem.l1.accesses"), 2 * hits) << "96 bytes span two lines";
  EXPECT_GT(test::stat(on, "shader.reads.dram_read_bytes"), 0);
  EXPECT_GT(test::stat(on, "mem.l2.accesses"), test::stat(off, "mem.l2.accesses"))
      << "shading reads compete with BVH reads in the L2";
  EXPECT_GT(test::stat(on, "cycles"), test::stat(off, "cycles"));
  EXPECT_GT(on["utilisation"]["mean"]["shader"].get<double>(), 0);
  EXPECT_EQ(on["shader"]["busy_cycles"].get<double>(), test::stat(on, "shader.raygen_cycles") +
                                                           test::stat(on, "shader.hit_cycles") +
                                                           test::stat(on, "shader.miss_cycles"));

  nlohmann::json slower =
      test::simulate(machine(GetParam(), {"shader.model=\"simt\"", "shader.warps=3",
                                          "shader.camera.hit=3000", "shader.diffuse_gi.hit=3000"}),
                     s.scene, rays);
  EXPECT_GT(test::stat(slower, "cycles"), 2 * test::stat(on, "cycles"))
      << "long hit shading holds the warp slots";
  EXPECT_GT(test::stat(slower, "shader.slot_wait_cycles"), 0);
}

INSTANTIATE_TEST_SUITE_P(Modes, SimShader, ::testing::Values("depth_first", "packet"));

TEST(SimShader, ModelNoneIgnoresTheShaderKeys) {
  test::SimScene s("cornell");
  std::vector<Ray> rays = test::mixed_rays(s.scene, 200, 9);
  nlohmann::json plain = test::simulate(machine("depth_first", {}), s.scene, rays);
  nlohmann::json keyed = test::simulate(
      machine("depth_first",
              {"shader.warps=1", "shader.bytes_per_hit=4096", "shader.camera.hit=9"}),
      s.scene, rays);
  plain.erase("config");
  keyed.erase("config");
  EXPECT_EQ(plain, keyed);
}

}  // namespace
}  // namespace rtsim
