// Whole simulations of an alpha-tested scene (traces/alpha.h): every ray retires with Embree's
// filtered answer, every candidate on a masked triangle is one any-hit call that reads one texel,
// and the calls' round trips show in the cycles.
#include <gtest/gtest.h>

#include <random>

#include "tests/alpha_layers.h"
#include "tests/sc/sim_test_util.h"

namespace rtsim {
namespace {

// Rays straight down through the layers at random points, every other one a shadow query.
std::vector<Ray> down_rays(size_t n) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> at(0.01f, 1.99f);
  std::vector<Ray> rays(n);
  for (size_t i = 0; i < n; ++i) {
    rays[i].org = {at(rng), at(rng), 1.0f};
    rays[i].dir = {0.0f, 0.0f, -1.0f};
    if (i % 2) {
      rays[i].query = Query::AnyHit;
      rays[i].type = RayType::Shadow;
    }
  }
  return rays;
}

nlohmann::json run(const char* mode, uint32_t latency) {
  Scene scene;
  scene.source = "test:alpha_layers";
  scene.mesh = test::layered(5);
  return test::simulate(load_hw_config("", {std::string("rt.mode=\"") + mode + "\"",
                                            "shader.anyhit_latency=" + std::to_string(latency)}),
                        scene, down_rays(2000), true);
}

class SimAlpha : public ::testing::TestWithParam<const char*> {};

TEST_P(SimAlpha, EveryCandidateIsOneCallReadingOneTexelAndRoundTripsCostCycles) {
  nlohmann::json doc = run(GetParam(), 60);
  EXPECT_EQ(doc["verify"]["rays"], 2000);
  EXPECT_EQ(doc["verify"]["unexplained"], 0) << doc["verify"].dump();
  double calls = test::stat(doc, "anyhit.calls");
  double per_type = test::stat(doc, "type.camera.trav_alpha_tests") +
                    test::stat(doc, "type.shadow.trav_alpha_tests");
  EXPECT_EQ(calls, per_type);
  EXPECT_GT(calls, 2000) << "half the candidates fall in holes: rays pass several layers";
  EXPECT_EQ(test::stat(doc, "anyhit.texture.mem.l1.accesses"), calls) << "a texel is one line";
  EXPECT_LE(test::stat(doc, "anyhit.texture.dram_read_bytes"), 64) << "one 16-byte texture";
  EXPECT_GE(test::stat(doc, "anyhit.wait_cycles"), 60 * calls);
  EXPECT_EQ(
      test::stat(doc, "anyhit.wait_cycles"),
      test::stat(doc, "type.camera.anyhit_cycles") + test::stat(doc, "type.shadow.anyhit_cycles"));
  double slower = test::stat(run(GetParam(), 600), "cycles");
  EXPECT_GT(slower, 2 * test::stat(doc, "cycles")) << "a longer round trip shows in the cycles";
}

INSTANTIATE_TEST_SUITE_P(Modes, SimAlpha, ::testing::Values("depth_first", "treelet", "packet"));

TEST(SimAlpha, AnOpaqueSceneHasNoAnyHitStats) {
  Scene scene;
  scene.source = "test:opaque";
  scene.mesh = test::layered(2);
  scene.mesh.alpha = nullptr;
  nlohmann::json doc = test::simulate(load_hw_config(""), scene, down_rays(100));
  EXPECT_FALSE(doc["stats"]["counters"].contains("anyhit.calls"));
  EXPECT_FALSE(doc["stats"]["counters"].contains("rt0.anyhit.requests"));
}

}  // namespace
}  // namespace rtsim
