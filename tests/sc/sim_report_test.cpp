// The results a run writes: the stats document has every figure issue 5 asks for, with the
// resolved config, and the per-pixel buffers match the stream's image. Also the memory
// modules' write path (stack spills): caches write around, the DRAM charges its bus.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "model/sc/shared_levels_module.h"
#include "model/sc/tlm_memory.h"
#include "tests/mem/mock_memory.h"
#include "tests/sc/sim_test_util.h"

namespace rtsim {
namespace {

TEST(SimReport, StatsDocumentHasEveryFigure) {
  test::SimScene s;
  std::vector<Ray> rays = test::mixed_rays(s.scene, 500, 2);
  HwConfig config = test::small_machine();
  config.rt.mode = TraversalMode::Packet;
  config.rt.stack.entries = 2;
  nlohmann::json doc = test::simulate(config, s.scene, rays, false, 32, 24);
  EXPECT_EQ(doc["schema"], kSimStatsSchema);
  for (const char* key : {"cycles", "rays_per_cycle", "mrays_per_second", "clock_ghz"})
    EXPECT_TRUE(doc["summary"].contains(key)) << key;
  for (auto& [type, t] : doc["ray_types"].items()) {
    for (const char* p : {"p50", "p95", "p99"}) EXPECT_TRUE(t["latency_cycles"].contains(p));
    EXPECT_LE(t["latency_cycles"]["p50"], t["latency_cycles"]["p99"]) << type;
    for (const char* key :
         {"nodes_per_ray", "triangles_per_ray", "l1_hit_rate", "l2_hit_rate", "dram_bytes_per_ray"})
      EXPECT_TRUE(t.contains(key)) << type << " " << key;
  }
  for (const char* unit : {"box", "triangle", "control", "ray_slots"}) {
    double u = doc["utilisation"]["units"]["rt1"][unit].get<double>();
    EXPECT_GE(u, 0.0) << unit;
    EXPECT_LE(u, 1.0) << unit;
  }
  const nlohmann::json& m = doc["memory"];
  for (const char* level : {"l1", "l2"}) {
    double hit = m[std::string(level) + "_hit_rate"].get<double>();
    double served = m[std::string(level) + "_served_rate"].get<double>();
    EXPECT_GE(served, hit) << level << ": merges are served without going below, not hits";
    EXPECT_LE(served, 1.0) << level;
  }
  double compulsory = m["l2_compulsory_share"].get<double>();
  EXPECT_GT(compulsory, 0.0) << "a cold start misses every line once";
  EXPECT_LE(compulsory, 1.0);
  double simd = doc["coherence"]["simd_efficiency"].get<double>();
  EXPECT_GT(simd, 0.0);
  EXPECT_LE(simd, 1.0);
  EXPECT_GE(doc["coherence"]["distinct_nodes_per_warp_step"].get<double>(), 1.0);
  EXPECT_TRUE(doc["coherence"]["rays_per_treelet_visit"].is_null()) << "not a treelet run";
  EXPECT_GT(doc["stack"]["spill_entries"].get<double>(), 0.0) << "a 2-entry stack spills";
  EXPECT_EQ(doc["pixel_buffers"]["width"], 32);
  EXPECT_EQ(doc["config"]["rt"]["mode"], "packet") << "the resolved config rides along";
  EXPECT_TRUE(doc["stats"]["counters"].contains("mem.l1.rt0.hits"));
  EXPECT_TRUE(doc["stats"]["derived"].contains("mem.l1.rt0.hit_rate"));
}

TEST(SimReport, WritesStatsConfigAndPixelFiles) {
  test::SimScene s;
  std::vector<Ray> rays = sample_camera_rays(s.scene.mesh, 16, 8);
  std::string dir = ::testing::TempDir() + "rtsim-sim-report-" + std::to_string(getpid());
  std::string listing = run_in_child([&] {
    HwConfig config = test::small_machine();
    BvhImage image = build_bvh_image(s.scene.mesh, config.bvh);
    VectorRaySource source(rays);
    RtSimulator sim(config, image, source, 16, 8);
    sim.run();
    SimRunInfo info;
    info.bvh = image;
    write_sim_results(dir, sim, info);
    std::string out;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      out += entry.path().filename().string() + "=" + std::to_string(entry.file_size()) + ";";
    return out;
  });
  for (const char* f : {"pixel_cycles.f32=512;", "pixel_nodes.f32=512;",
                        "pixel_dram_bytes.f32=512;", "stats.json="})
    EXPECT_NE(listing.find(f), std::string::npos) << f << " in " << listing;
  // The written config loads back to the same resolved config.
  HwConfig reread = load_hw_config(dir + "/config.toml");
  EXPECT_EQ(resolved_toml(reread), resolved_toml(test::small_machine()));
  std::filesystem::remove_all(dir);
}

// Writes `bytes` of local memory, then reads its first line back, through its L1 at cycle 0.
struct Writer : sc_core::sc_module {
  UnitMemory l1;
  test::RecordingClient client;
  uint32_t bytes;
  SC_HAS_PROCESS(Writer);
  Writer(sc_core::sc_module_name name, uint32_t bytes)
      : sc_module(name), l1("l1", CacheConfig{1024, 64, 2, "lru", 2, 4}), bytes(bytes) {
    SC_METHOD(run);
  }
  void run() {
    l1.cache().write(kLocalMemoryBase, bytes, 0);
    ReadCharge charge;
    l1.cache().read(kLocalMemoryBase, 64, 0, &client, 0, charge);
  }
};

// "L1 write-backs, L2 write-backs, DRAM bytes written, L2 hits, ready cycle of the read".
std::string write_then_read(uint32_t bytes) {
  return run_in_child([bytes] {
    Clock clock;
    Writer writer("writer", bytes);
    SharedLevelsModule l2("l2", CacheConfig{4096, 64, 4, "lru", 10, 4}, clock);
    DramModule dram("dram", DramConfig{16.0, 100, 8}, clock);
    writer.l1.connect(l2);
    l2.out.bind(dram.in);
    sc_core::sc_start();
    const CacheStats& s1 = writer.l1.cache().stats();
    CacheStats s2 = l2.instances()[0].stats();
    return std::to_string(s1.writebacks) + " " + std::to_string(s2.writebacks) + " " +
           std::to_string(dram.dram().stats().write_bytes) + " " + std::to_string(s2.hits) + " " +
           std::to_string(writer.client.done.at(0).ready);
  });
}

TEST(SimReport, SpillsAreWrittenBackThroughTheCachesToDram) {
  // 2 KiB through a 1 KiB L1 (8 sets of 2 ways): its first 16 lines are written back to the
  // L2 (after the L1's 2-cycle tag check), and the read's miss evicts one more; the L2 holds
  // them all, and the read finds its line there: ready at 2 + 10.
  EXPECT_EQ(write_then_read(2048), "17 0 0 1 12");
  // 8 KiB: 113 lines reach the 4 KiB L2 (16 sets of 4 ways), 8 in set 0 and 7 in each other
  // set, so it writes 4 + 15 x 3 back to DRAM, and one more for the read's miss in set 0:
  // 50 lines, 3200 bytes.
  std::string big = write_then_read(8192);
  EXPECT_EQ(big.substr(0, big.rfind(' ')), "113 50 3200 0");
}

}  // namespace
}  // namespace rtsim
