// The SEED mGPU flow as a cost model: ray generation on the primary, inputs copied to the
// others, tracing everywhere, results copied back, filtering on the primary. Exact numbers.
#include <gtest/gtest.h>

#include "model/multi/mgpu_flow.h"

namespace rtsim::multi {
namespace {

// 1 ns per pixel of ray generation, 2 of filtering; 10 B/ns (10 GB/s), 1 us per copy;
// 4 B in per pixel, 2 B per sample, 1 B per ray; 8 B back per pixel.
FlowConfig test_flow(bool shared) {
  FlowConfig f;
  f.raygen_ns_per_pixel = 1;
  f.filter_ns_per_pixel = 2;
  f.input_bytes_per_pixel = 4;
  f.bytes_per_sample = 2;
  f.bytes_per_ray = 1;
  f.output_bytes_per_pixel = 8;
  f.link = {10.0, 1.0, shared};
  return f;
}

TEST(MgpuFlow, OneDeviceIsRaygenTraceFilter) {
  FlowConfig flow = test_flow(true);
  FrameTiming t = time_frame(flow, 1000, {{1000, 1500, 9000, 50000}});
  EXPECT_DOUBLE_EQ(t.frame_ns, 1000 + 50000 + 2000);
  EXPECT_DOUBLE_EQ(t.frame_ns, single_device_frame_ns(flow, 1000, 50000));
  EXPECT_EQ(t.copy_bytes, 0u);
  EXPECT_DOUBLE_EQ(t.copy_overhead_ns, 0);
  EXPECT_DOUBLE_EQ(t.devices[0].idle_ns, 0) << "the primary is busy the whole frame";
}

TEST(MgpuFlow, TwoDevicesCopyInTraceCopyBackFilter) {
  FrameTiming t =
      time_frame(test_flow(true), 1000, {{600, 100, 1000, 20000}, {400, 200, 3000, 20000}});
  // Device 1's inputs: 400 * 4 + 200 * 2 + 3000 * 1 = 5000 B -> 1000 + 500 ns after raygen.
  const DeviceTiming& d1 = t.devices[1];
  EXPECT_EQ(d1.bytes_in, 5000u);
  EXPECT_DOUBLE_EQ(d1.copy_in_ns, 1500);
  EXPECT_DOUBLE_EQ(d1.start_ns, 1000 + 1500);
  EXPECT_DOUBLE_EQ(d1.end_ns, 2500 + 20000);
  // Results: 400 * 8 = 3200 B -> 1000 + 320 ns; filtering starts when they arrive.
  EXPECT_EQ(d1.bytes_out, 3200u);
  EXPECT_DOUBLE_EQ(d1.results_ns, 22500 + 1320);
  EXPECT_DOUBLE_EQ(t.frame_ns, 23820 + 2000);
  EXPECT_DOUBLE_EQ(t.devices[0].start_ns, 1000) << "the primary traces right after raygen";
  EXPECT_DOUBLE_EQ(t.copy_ns, 1500 + 1320);
  EXPECT_EQ(t.copy_bytes, 8200u);
  EXPECT_DOUBLE_EQ(t.copy_overhead_ns, t.frame_ns - (1000 + 20000 + 2000));
  EXPECT_DOUBLE_EQ(t.devices[0].busy_ns, 1000 + 20000 + 2000);
  EXPECT_DOUBLE_EQ(t.devices[0].idle_ns, t.frame_ns - 23000);
  EXPECT_DOUBLE_EQ(d1.idle_ns, t.frame_ns - 20000);
}

TEST(MgpuFlow, SharedCopyQueueSerialisesCopiesADedicatedLinkDoesNot) {
  std::vector<DeviceLoad> loads{{100, 0, 0, 5000}, {250, 0, 0, 5000}, {250, 0, 0, 5000}};
  // Inputs: 250 * 4 = 1000 B -> 1000 + 100 ns each. Results: 2000 B -> 1000 + 200 ns each.
  FrameTiming shared = time_frame(test_flow(true), 600, loads);
  EXPECT_DOUBLE_EQ(shared.devices[1].start_ns, 600 + 1100);
  EXPECT_DOUBLE_EQ(shared.devices[2].start_ns, 600 + 2200) << "waits for device 1's copy";
  EXPECT_DOUBLE_EQ(shared.devices[1].results_ns, 1700 + 5000 + 1200);
  EXPECT_DOUBLE_EQ(shared.devices[2].results_ns, 7900 + 1200) << "after device 1's results";
  FrameTiming dedicated = time_frame(test_flow(false), 600, loads);
  EXPECT_DOUBLE_EQ(dedicated.devices[1].start_ns, 1700);
  EXPECT_DOUBLE_EQ(dedicated.devices[2].start_ns, 1700) << "its own link";
  EXPECT_LT(dedicated.frame_ns, shared.frame_ns);
}

TEST(MgpuFlow, ResultsQueueInTheOrderDevicesFinish) {
  // Device 2 finishes long before device 1; its copy back goes first.
  std::vector<DeviceLoad> loads{{0, 0, 0, 0}, {250, 0, 0, 90000}, {250, 0, 0, 1000}};
  FrameTiming t = time_frame(test_flow(true), 500, loads);
  EXPECT_DOUBLE_EQ(t.devices[2].results_ns, t.devices[2].end_ns + 1200);
  EXPECT_DOUBLE_EQ(t.devices[1].results_ns, t.devices[1].end_ns + 1200);
}

TEST(MgpuFlow, EmptyRegionCopiesNothing) {
  FrameTiming t = time_frame(test_flow(true), 100, {{100, 10, 10, 3000}, {0, 0, 0, 0}});
  EXPECT_DOUBLE_EQ(t.devices[1].copy_in_ns, 0);
  EXPECT_DOUBLE_EQ(t.devices[1].copy_out_ns, 0);
  EXPECT_DOUBLE_EQ(t.frame_ns, 100 + 3000 + 200);
}

TEST(MaxDeviation, OfTheMeanInPercent) {
  EXPECT_DOUBLE_EQ(max_deviation_pct({90, 100, 110, 100}), 10);
  EXPECT_DOUBLE_EQ(max_deviation_pct({100, 100}), 0);
  EXPECT_DOUBLE_EQ(max_deviation_pct({50, 150}), 50);
  EXPECT_DOUBLE_EQ(max_deviation_pct({0, 0}), 0) << "an empty frame deviates by nothing";
  EXPECT_DOUBLE_EQ(max_deviation_pct({}), 0);
  EXPECT_DOUBLE_EQ(max_deviation_pct({7}), 0) << "M = 1";
}

}  // namespace
}  // namespace rtsim::multi
