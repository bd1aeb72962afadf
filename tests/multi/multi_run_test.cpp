// The driver over a stream with a backend of known speed: each ray costs 100 cycles of one RT
// unit, so a device takes rays * 100 / rt_units / clock ns. With it the balancers' behaviour
// is exact: irregular samples, heterogeneous and changing devices, empty frames, M = 1.
#include <gtest/gtest.h>

#include <cmath>

#include "model/multi/multi_run.h"
#include "model/multi/multi_summary.h"
#include "synthetic_frames.h"
#include "traces/error.h"

namespace rtsim::multi {
namespace {

const std::string kMobile = std::string(RTSIM_SOURCE_DIR) + "/configs/mobile.toml";

class LinearBackend : public DeviceBackend {
 public:
  std::vector<DeviceResult> run(const std::vector<DeviceTask>& tasks,
                                const ScreenLayout& layout) override {
    tasks_per_call.push_back(tasks.size());
    std::vector<DeviceResult> out;
    for (const DeviceTask& t : tasks) {
      DeviceResult r;
      r.rays = t.rays.size();
      r.cycles = r.rays * 100 / t.config->rt_units;
      r.time_ns = double(r.cycles) / t.config->clock_ghz;
      r.cost.assign(t.region.size(), 0.0f);
      for (const Ray& ray : t.rays) {
        r.type_rays[size_t(ray.type)] += 1;
        r.type_cycles[size_t(ray.type)] += 100;
        uint32_t p = ray.pixel < layout.pixels() ? layout.position_of(ray.pixel) : 0;
        if (p >= t.region.begin && p < t.region.end) r.cost[p - t.region.begin] += 100;
      }
      out.push_back(r);
    }
    return out;
  }
  std::vector<size_t> tasks_per_call;  // one call per frame
};

DeviceSet mobile_set(uint32_t devices, std::vector<std::string> last_device_sets = {}) {
  DeviceSet set;
  set.devices.assign(devices, DeviceHardware{kMobile, {}});
  set.devices.back().sets = last_device_sets;
  return set;
}

MultiRunResult run(const std::string& stream, const DeviceSet& set, LinearBackend* used = nullptr) {
  RayStreamReader reader(stream);
  DeviceConfigs configs(set);
  LinearBackend backend;
  MultiRunResult r = run_multi_device(reader, set, configs, backend);
  if (used) *used = backend;
  return r;
}

std::vector<StrategySummary> summaries(const MultiRunResult& r, double settle_pct = 5.0) {
  std::vector<StrategySummary> out;
  for (const StrategyRun& run : r.runs)
    out.push_back(summarize(run, r.devices, change_frames(r), settle_pct));
  return out;
}

TEST(MultiRun, BalancersBeatStaticOnIrregularSamples) {
  test::SyntheticFrames s;
  s.frames = 10;
  LinearBackend backend;
  MultiRunResult r =
      run(test::write_synthetic_stream("irregular", s, "x", 1), mobile_set(4), &backend);
  ASSERT_EQ(r.runs.size(), 4u);
  ASSERT_EQ(backend.tasks_per_call.size(), 10u);
  EXPECT_EQ(backend.tasks_per_call[0], 1u + 4 + 4) << "the balancers share frame 0's split";
  std::vector<StrategySummary> sum = summaries(r);
  EXPECT_GT(sum[0].avg_max_dev_pct, 10.0) << "static: samples and cost are not even";
  EXPECT_LT(sum[1].avg_max_dev_pct, 3.0) << "balanced: every ray is a sample";
  EXPECT_LT(sum[2].avg_max_dev_pct, 3.0) << "cost-weighted";
  EXPECT_LT(sum[3].avg_max_dev_pct, 1.0) << "current: the frame's own rays, no lag";
  EXPECT_EQ(r.runs[0].frames[0].devices[0].region, (Region{0, 576})) << "static: by area";
  for (const StrategyRun& run : r.runs) {
    ASSERT_EQ(run.frames.size(), 10u);
    if (run.strategy != SplitStrategy::Static) {
      EXPECT_LT(run.frames[0].max_deviation_pct, 1.0) << "frame 0: on the CDF of its own rays";
    }
    for (const FrameRecord& f : run.frames) {
      uint64_t rays = 0, samples = 0, camera = 0;
      for (const DeviceFrame& d : f.devices) rays += d.rays, samples += d.samples;
      std::vector<Ray> frame_rays = test::synthetic_frame(s, f.frame);
      for (const Ray& ray : frame_rays) camera += ray.type == RayType::Camera;
      EXPECT_EQ(rays, frame_rays.size()) << "every ray traced once";
      EXPECT_EQ(samples, camera) << "the report's samples are camera samples";
      EXPECT_GT(f.speedup, 1.0);
      EXPECT_GT(f.timing.copy_overhead_ns, 0.0);
    }
  }
}

TEST(MultiRun, CountingCameraSamplesMissesTheRaysBehindThem) {
  test::SyntheticFrames s;
  s.frames = 10;
  DeviceSet set = mobile_set(4);
  set.samples = SampleUnit::Camera;
  MultiRunResult r = run(test::write_synthetic_stream("camera", s, "x", 1), set);
  std::vector<StrategySummary> sum = summaries(r);
  EXPECT_LT(sum[1].avg_max_dev_pct, sum[0].avg_max_dev_pct / 2) << "balanced";
  EXPECT_GT(sum[1].avg_max_dev_pct, 3.0) << "the costly blob's extra rays are not samples";
  EXPECT_LT(sum[2].avg_max_dev_pct, sum[1].avg_max_dev_pct) << "cost sees them";
  EXPECT_FALSE(r.runs[1].frames[0].devices[0].region == (Region{0, 576}))
      << "frame 0 splits on the CDF of its camera samples";
}

TEST(MultiRun, HeterogeneousDevicesConvergeAndSettleAfterAChange) {
  test::SyntheticFrames s;
  s.frames = 12;
  s.extra_rays = 0;  // cost follows the samples: every balancer can settle
  DeviceSet set = mobile_set(4, {"rt.count=2"});            // the last device has half the units
  set.changes.push_back({6, 0, {"", {"clock.ghz=0.45"}}});  // the primary throttles at 6
  MultiRunResult r = run(test::write_synthetic_stream("hetero", s, "x", 1), set);
  EXPECT_EQ(change_frames(r), (std::vector<uint32_t>{6}));
  std::vector<StrategySummary> sum = summaries(r);
  for (size_t k : {1, 2, 3}) {
    const StrategySummary& b = sum[k];
    ASSERT_EQ(b.settle.size(), 2u);
    EXPECT_EQ(b.settle[0].frame, 0u);
    EXPECT_GE(b.settle[0].settle_frames, 0) << strategy_name(b.strategy);
    EXPECT_LE(b.settle[0].settle_frames, 3) << strategy_name(b.strategy);
    EXPECT_EQ(b.settle[1].frame, 6u);
    EXPECT_GE(b.settle[1].settle_frames, 0) << strategy_name(b.strategy);
    EXPECT_LE(b.settle[1].settle_frames, 3) << strategy_name(b.strategy);
    const FrameRecord& last = r.runs[k].frames.back();
    EXPECT_NEAR(double(last.devices[0].rays) / double(last.devices[1].rays), 0.5, 0.1)
        << "the throttled primary";
    EXPECT_NEAR(double(last.devices[3].rays) / double(last.devices[1].rays), 0.5, 0.1)
        << "half the units";
  }
  EXPECT_EQ(sum[0].settle[0].settle_frames, -1) << "static never balances unequal devices";
  // The cost balancer gives the half device about half the cost of a full one.
  const FrameRecord& f5 = r.runs[2].frames[5];
  EXPECT_NEAR(f5.devices[3].cost / f5.devices[1].cost, 0.5, 0.05);
}

TEST(MultiRun, EmptyFrameLeavesAValidSplit) {
  test::SyntheticFrames s;
  s.frames = 4;
  MultiRunResult r = run(test::write_synthetic_stream("empty", s, "x", 1, {1}), mobile_set(3));
  for (const StrategyRun& run : r.runs) {
    ASSERT_EQ(run.frames.size(), 4u);
    const FrameRecord& empty = run.frames[1];
    EXPECT_EQ(empty.max_deviation_pct, 0.0);
    for (const DeviceFrame& d : empty.devices) EXPECT_EQ(d.rays, 0u);
    EXPECT_GT(empty.timing.frame_ns, 0.0) << "ray generation and filtering still run";
    for (const FrameRecord& f : run.frames) {
      Split split;
      for (const DeviceFrame& d : f.devices) split.push_back(d.region);
      EXPECT_EQ(split_problem(split, s.width * s.height), "") << "frame " << f.frame;
    }
    if (run.strategy != SplitStrategy::Static) {
      EXPECT_LT(run.frames[3].max_deviation_pct, 10.0) << strategy_name(run.strategy);
    }
  }
}

TEST(MultiRun, OneDeviceIsTheBaseline) {
  test::SyntheticFrames s;
  s.frames = 3;
  MultiRunResult r = run(test::write_synthetic_stream("one", s, "x", 1), mobile_set(1));
  for (const StrategyRun& run : r.runs)
    for (const FrameRecord& f : run.frames) {
      EXPECT_DOUBLE_EQ(f.speedup, 1.0);
      EXPECT_EQ(f.timing.copy_bytes, 0u);
      EXPECT_EQ(f.max_deviation_pct, 0.0);
      EXPECT_EQ(f.devices[0].region, (Region{0, s.width * s.height}));
    }
}

TEST(MultiRun, RaysOutOfFrameOrderAreAnInputError) {
  std::string path = test::scratch_path("order.rays");
  StreamHeader h;
  h.frame_count = 3;
  h.width = h.height = 2;
  {
    RayStreamWriter w(path, h);
    for (uint32_t frame : {0u, 2u, 1u}) {
      Ray ray;
      ray.frame = frame;
      w.write(ray);
    }
    w.finish();
  }
  try {
    run(path, mobile_set(2));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not in frame order"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rtsim::multi
