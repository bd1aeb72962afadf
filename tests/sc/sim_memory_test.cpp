// The memory side of whole simulations on every preset: with the DRAM lightly loaded, its mean
// latency is the unloaded latency the config implies (requests are served in time order, so
// none waits behind a request dated later).
#include <gtest/gtest.h>

#include <filesystem>

#include "model/config/hw_config.h"
#include "tests/sc/sim_test_util.h"

namespace rtsim {
namespace {

TEST(SimMemory, LightlyLoadedDramHasItsUnloadedLatencyOnEveryPreset) {
  test::SimScene s;
  std::vector<Ray> rays = test::mixed_rays(s.scene, 4000, 7);
  int presets = 0;
  for (const auto& entry : std::filesystem::directory_iterator(RTSIM_SOURCE_DIR "/configs")) {
    if (entry.path().extension() != ".toml") continue;
    ++presets;
    HwConfig config = load_hw_config(entry.path().string(), {});
    nlohmann::json doc = test::simulate(config, s.scene, rays);
    std::string name = entry.path().filename().string();
    double utilisation = test::stat(doc, "dram.utilisation");
    ASSERT_LT(utilisation, 0.10) << name << ": the stream must load the DRAM lightly";
    uint32_t block = block_bytes(config.l2);
    double unloaded = config.dram.latency + block / config.dram.bytes_per_cycle;
    double mean = test::stat(doc, "dram.mean_latency");
    EXPECT_NEAR(mean / unloaded, 1.0, 0.10)
        << name << ": mean DRAM latency " << mean << " at " << utilisation * 100
        << "% utilisation, unloaded " << unloaded;
  }
  EXPECT_GE(presets, 8);
}

TEST(SimMemory, L1MissesWaitingForMshrsJoinTheL2InOrderWhateverTheLatencies) {
  // An L1 tag check longer than the L2's hit: misses freed by an L2 response are dated inside
  // the window the L2 is serving, and must be served in their turn there.
  test::SimScene s;
  std::vector<Ray> rays = test::mixed_rays(s.scene, 1000, 8);
  HwConfig config = test::small_machine();
  config.l1.hit_latency = 40;
  config.l1.mshrs = 2;
  config.l2.hit_latency = 3;
  config.dram.latency = 0;
  nlohmann::json doc = test::simulate(config, s.scene, rays, true);
  EXPECT_EQ(doc["verify"]["unexplained"], 0);
  EXPECT_EQ(test::stat(doc, "rays"), double(rays.size()));
  EXPECT_GT(test::stat(doc, "rt0.l1.mshr_stall_cycles"), 0.0) << "misses waited for MSHRs";
}

TEST(SimMemory, DepthFirstAndTreeletModesMissTheSameBlocksCompulsorily) {
  // Spilled stacks live in cached local memory and refill from there, so the compulsory misses
  // of both modes are the BVH blocks the rays touch, whatever the stack traffic.
  test::SimScene s;
  std::vector<Ray> rays = test::mixed_rays(s.scene, 3000, 9);
  HwConfig config = test::small_machine();
  config.rt.stack.entries = 1;
  config.l2_layout.slices = 4;  // lines written through to the L2 go to their own slice
  nlohmann::json depth_first = test::simulate(config, s.scene, rays);
  config.rt.mode = TraversalMode::Treelet;
  config.treelet_queues.max_rays = 4096;  // many ray contexts, each spilling into fresh lines
  nlohmann::json treelet = test::simulate(config, s.scene, rays);
  ASSERT_GT(test::stat(depth_first, "rt.stack.spill_entries"), 0.0);
  ASSERT_GT(test::stat(treelet, "rt.stack.spill_entries"), 0.0);
  ASSERT_GT(test::stat(treelet, "rt.postponed"), 0.0);
  EXPECT_EQ(test::stat(depth_first, "l2.cold_misses"), test::stat(treelet, "l2.cold_misses"));
}

}  // namespace
}  // namespace rtsim
