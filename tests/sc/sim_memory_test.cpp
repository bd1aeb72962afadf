// The memory side of whole simulations on every preset: with the DRAM lightly loaded, its mean
// latency is the unloaded latency the config implies (requests are served in time order, so
// none waits behind a request dated later).
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "model/config/hw_config.h"
#include "tests/sc/sim_test_util.h"
#include "tests/sc/timed_memory.h"

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
    uint32_t block = block_bytes(last_level(config).cache);
    double unloaded = config.dram.latency + block / config.dram.bytes_per_cycle;
    double mean = test::stat(doc, "dram.mean_latency");
    EXPECT_NEAR(mean / unloaded, 1.0, 0.10)
        << name << ": mean DRAM latency " << mean << " at " << utilisation * 100
        << "% utilisation, unloaded " << unloaded;
  }
  EXPECT_GE(presets, 8);
}

TEST(SimMemory, AThirdPartyTimedMemoryRunsAWholeSimulation) {
  // A DRAMSys-style approximately-timed target bound where the DRAM is: every ray verified,
  // and with a 300 ns memory (1 GHz) the run is slower than with the built-in banked DRAM.
  test::SimScene s;
  std::vector<Ray> rays = test::mixed_rays(s.scene, 500, 4);
  HwConfig config = test::small_machine();
  config.dram_model = DramModel::Banked;
  nlohmann::json banked = test::simulate(config, s.scene, rays, true);
  std::string result = run_in_child([&] {
    BvhImage image = build_bvh_image(s.scene.mesh, config.bvh);
    VectorRaySource source(rays);
    test::TimedMemory memory("memory", sc_core::sc_time(300, sc_core::SC_NS));
    RtSimulator sim(config, image, source, 0, 0, nullptr, [&](SharedLevelsModule& l2) {
      l2.out.bind(memory.in);
      l2.use_timed_memory(0);
    });
    sim.run();
    return std::to_string(sim.rays()) + " " + std::to_string(sim.cycles()) + " " +
           std::to_string(memory.reads) + " " + std::to_string(sim.l2_stats().misses);
  });
  std::istringstream in(result);
  uint64_t finished = 0, cycles = 0, reads = 0, misses = 0;
  in >> finished >> cycles >> reads >> misses;
  EXPECT_EQ(finished, rays.size());
  EXPECT_EQ(reads, misses) << "every L2 miss reached the foreign memory";
  EXPECT_GT(cycles, test::stat(banked, "cycles"));
  EXPECT_EQ(banked["verify"]["unexplained"], 0);
  EXPECT_GT(test::stat(banked, "dram.row_hits"), 0.0);
}

TEST(SimMemory, L1MissesWaitingForMshrsJoinTheL2InOrderWhateverTheLatencies) {
  // An L1 tag check longer than the L2's hit: misses freed by an L2 response are dated inside
  // the window the L2 is serving, and must be served in their turn there.
  test::SimScene s;
  std::vector<Ray> rays = test::mixed_rays(s.scene, 1000, 8);
  HwConfig config = test::small_machine();
  first_level(config).cache.hit_latency = 40;
  first_level(config).cache.mshrs = 2;
  last_level(config).cache.hit_latency = 3;
  config.dram.latency = 0;
  nlohmann::json doc = test::simulate(config, s.scene, rays, true);
  EXPECT_EQ(doc["verify"]["unexplained"], 0);
  EXPECT_EQ(test::stat(doc, "rays"), double(rays.size()));
  EXPECT_GT(test::stat(doc, "mem.l1.rt0.mshr_stall_cycles"), 0.0) << "misses waited for MSHRs";
}

TEST(SimMemory, DepthFirstAndTreeletModesMissTheSameBlocksCompulsorily) {
  // Spilled stacks live in cached local memory and refill from there, so the compulsory misses
  // of both modes are the BVH blocks the rays touch, whatever the stack traffic.
  test::SimScene s;
  std::vector<Ray> rays = test::mixed_rays(s.scene, 3000, 9);
  HwConfig config = test::small_machine();
  config.rt.stack.entries = 1;
  last_level(config).slices = 4;  // lines written through to the L2 go to their own slice
  nlohmann::json depth_first = test::simulate(config, s.scene, rays);
  config.rt.mode = TraversalMode::Treelet;
  config.treelet_queues.max_rays = 4096;  // many ray contexts, each spilling into fresh lines
  nlohmann::json treelet = test::simulate(config, s.scene, rays);
  ASSERT_GT(test::stat(depth_first, "rt.stack.spill_entries"), 0.0);
  ASSERT_GT(test::stat(treelet, "rt.stack.spill_entries"), 0.0);
  ASSERT_GT(test::stat(treelet, "rt.postponed"), 0.0);
  EXPECT_EQ(test::stat(depth_first, "mem.l2.cold_misses"),
            test::stat(treelet, "mem.l2.cold_misses"));
}

}  // namespace
}  // namespace rtsim
