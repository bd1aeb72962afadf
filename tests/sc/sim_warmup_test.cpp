// Warm-up and region of interest: the stats of a run with sim.warmup_rays or
// sim.warmup_frames are what accrued after its warm-up (snapshot and subtract), and streams of
// several frames are reported per frame.
#include <gtest/gtest.h>

#include "tests/sc/sim_test_util.h"
#include "traces/error.h"

namespace rtsim {
namespace {

// The same rays `copies` times, each copy a frame.
std::vector<Ray> repeated(const std::vector<Ray>& rays, uint32_t copies) {
  std::vector<Ray> out;
  for (uint32_t c = 0; c < copies; ++c)
    for (Ray ray : rays) {
      ray.frame = c;
      out.push_back(ray);
    }
  return out;
}

TEST(SimWarmup, AWarmUpOfTheSameRaysLeavesNoCompulsoryMiss) {
  test::SimScene s;
  std::vector<Ray> rays = test::mixed_rays(s.scene, 800, 3);
  HwConfig config = test::small_machine();
  nlohmann::json cold = test::simulate(config, s.scene, repeated(rays, 3));
  // Two copies of warm-up: what the second's last rays still do after it counts, but finds
  // every block the first copy referenced.
  config.sim.warmup_rays = 2 * rays.size();
  nlohmann::json warm = test::simulate(config, s.scene, repeated(rays, 3));
  EXPECT_GT(test::stat(cold, "mem.l2.cold_misses"), 0.0);
  EXPECT_EQ(test::stat(warm, "mem.l2.cold_misses"), 0.0)
      << "every block was referenced in the warm-up";
  EXPECT_LT(warm["memory"]["l1_compulsory_share"].get<double>(),
            cold["memory"]["l1_compulsory_share"].get<double>() / 4)
      << "an L1 misses blocks only other units' L1s saw";
  EXPECT_EQ(warm["summary"]["rays"], rays.size()) << "warm-up rays are not measured";
  EXPECT_EQ(warm["ray_types"]["camera"]["rays"], 32 * 24);
  EXPECT_LT(test::stat(warm, "cycles"), test::stat(cold, "cycles"));
  EXPECT_LT(test::stat(warm, "mem.l2.misses"), test::stat(cold, "mem.l2.misses"));
  EXPECT_GT(warm["summary"]["measured_from_cycle"].get<double>(), 0.0);
  EXPECT_EQ(warm["memory"]["l2_compulsory_share"], 0.0);
}

TEST(SimWarmup, StreamsOfSeveralFramesAreReportedPerFrame) {
  test::SimScene s;
  std::vector<Ray> rays = test::mixed_rays(s.scene, 600, 4);
  HwConfig config = test::small_machine();
  nlohmann::json doc = test::simulate(config, s.scene, repeated(rays, 2));
  const nlohmann::json& frames = doc["frames"];
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0]["frame"], 0);
  EXPECT_EQ(frames[1]["frame"], 1);
  EXPECT_EQ(frames[0]["rays"].get<double>(), double(rays.size()));
  EXPECT_EQ(frames[1]["rays"].get<double>(), double(rays.size()));
  EXPECT_EQ(frames[0]["cycles"].get<double>() + frames[1]["cycles"].get<double>(),
            test::stat(doc, "cycles"))
      << "the frames split the run";
  EXPECT_GT(frames[0]["memory"]["l2_compulsory_share"].get<double>(),
            frames[1]["memory"]["l2_compulsory_share"].get<double>())
      << "the second frame finds what the first fetched";

  config.sim.warmup_frames = 1;
  nlohmann::json second = test::simulate(config, s.scene, repeated(rays, 2));
  EXPECT_EQ(second["summary"]["rays"], rays.size());
  EXPECT_TRUE(second["frames"].empty()) << "one measured frame: no per-frame list";
}

TEST(SimWarmup, AWarmUpAsLongAsTheStreamIsBadInput) {
  test::SimScene s;
  std::vector<Ray> rays = test::mixed_rays(s.scene, 50, 5);
  HwConfig config = test::small_machine();
  config.sim.warmup_rays = rays.size();
  std::string result = run_in_child([&] {
    try {
      test::simulate(config, s.scene, rays);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  });
  EXPECT_NE(result.find("[sim] warmup_rays"), std::string::npos) << result;
}

}  // namespace
}  // namespace rtsim
