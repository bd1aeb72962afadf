// Sample plans: windows inside their strata, in order, not overlapping, measuring about one
// ray in `rate`, with warm-up before each window, the same for the same seed.
#include <gtest/gtest.h>

#include "model/fidelity/sample_plan.h"
#include "traces/error.h"

namespace rtsim {
namespace {

TEST(SamplePlan, WindowsLieInTheirStrataInOrder) {
  SamplingConfig c;
  c.rate = 16;
  c.window_rays = 1000;
  c.warmup_rays = 300;
  SamplePlan plan = plan_samples(1000000, c, 256);
  ASSERT_EQ(plan.windows.size(), 1000000u / (16 * 1000)) << "one window per stratum";
  uint64_t previous_end = 0;
  for (const SampleWindow& w : plan.windows) {
    EXPECT_GE(w.begin, w.stratum_begin) << "window starts inside its stratum";
    EXPECT_LE(w.end, w.stratum_end) << "window ends inside its stratum";
    EXPECT_EQ(w.end - w.begin, 1000u) << "window measures window_rays";
    EXPECT_GE(w.warm_begin, previous_end) << "warm-up never overlaps the previous window";
    EXPECT_LE(w.begin - w.warm_begin, 300u) << "warm-up is at most warmup_rays";
    previous_end = w.end;
  }
  EXPECT_EQ(plan.windows.front().stratum_begin, 0u);
  EXPECT_EQ(plan.windows.back().stratum_end, 1000000u) << "strata cover the whole stream";
  double fraction = double(plan.measured_rays()) / 1e6;
  EXPECT_NEAR(fraction, 1.0 / 16, 0.01) << "about one ray in rate is measured";
}

TEST(SamplePlan, SameSeedSamePlanOtherSeedOtherOffsets) {
  SamplingConfig c;
  c.rate = 8;
  SamplePlan a = plan_samples(500000, c, 256), b = plan_samples(500000, c, 256);
  c.seed = 2;
  SamplePlan other = plan_samples(500000, c, 256);
  ASSERT_EQ(a.windows.size(), b.windows.size());
  bool differs = false;
  for (size_t i = 0; i < a.windows.size(); ++i) {
    EXPECT_EQ(a.windows[i].begin, b.windows[i].begin) << "deterministic for one seed";
    differs |= a.windows[i].begin != other.windows[i].begin;
  }
  EXPECT_TRUE(differs) << "another seed moves the windows";
}

TEST(SamplePlan, AutoSizesFollowTheRaySlots) {
  SamplePlan plan = plan_samples(10000000, SamplingConfig{}, 512);
  EXPECT_EQ(plan.window_rays, 4u * 512) << "auto window: 4 x ray slots";
  EXPECT_EQ(plan.warmup_rays, 512u) << "auto warm-up: the ray slots";
}

TEST(SamplePlan, ShortStreamsGetTwoStrataAndTooShortOnesAnError) {
  SamplingConfig c;
  c.rate = 4;
  SamplePlan plan = plan_samples(1000, c, 256);
  EXPECT_EQ(plan.windows.size(), 2u) << "at least two strata, for an interval";
  EXPECT_THROW(plan_samples(7, c, 256), InputError) << "fewer than 2 x rate rays";
}

}  // namespace
}  // namespace rtsim
