// Every fidelity level on one small stream: the functional counts are the traversal's, the
// cache level's memory figures are plausible, and the sampled level lands near the full cycle
// model with an interval. Timed levels run in forked children (SystemC elaborates once).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "model/config/hw_config.h"
#include "model/fidelity/cache_level.h"
#include "model/fidelity/functional_level.h"
#include "model/fidelity/level_runner.h"
#include "model/fidelity/scaled_level.h"
#include "model/units/traversal.h"
#include "tests/fidelity/fidelity_test_util.h"

namespace rtsim {
namespace {

class FidelityLevels : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    stream_ = new std::string(test::small_stream("grid:2000", 40000));
    scene_ = new Scene(load_scene("grid:2000"));
    config_ = new HwConfig(load_hw_config(""));
    image_ = new BvhImage(build_bvh_image(scene_->mesh, config_->bvh));
  }
  static void TearDownTestSuite() {
    std::filesystem::remove(*stream_);
    delete image_;
    delete config_;
    delete scene_;
    delete stream_;
  }
  static std::string* stream_;
  static Scene* scene_;
  static HwConfig* config_;
  static BvhImage* image_;
};
std::string* FidelityLevels::stream_;
Scene* FidelityLevels::scene_;
HwConfig* FidelityLevels::config_;
BvhImage* FidelityLevels::image_;

TEST_F(FidelityLevels, FunctionalCountsAreTheTraversalCounters) {
  FidelityResult r = run_functional_level(*image_, *stream_);
  TraversalUnit unit(*image_);
  TraversalState state;
  uint64_t nodes = 0, rays = 0;
  for (const Ray& ray : read_all_rays(*stream_)) {
    unit.trace(state, ray);
    nodes += state.counters.trav_nodes;
    ++rays;
  }
  EXPECT_EQ(r.rays, rays);
  EXPECT_DOUBLE_EQ(r.nodes_per_ray.value, double(nodes) / double(rays));
  EXPECT_FALSE(r.cycles.known) << "the functional level has no time";
  EXPECT_TRUE(r.levels.empty()) << "nor caches";
}

TEST_F(FidelityLevels, CacheLevelHasMemoryFiguresAndARooflineTime) {
  AnalyticTime bounds;
  CacheLevelTaps taps;
  taps.bounds = &bounds;
  FidelityResult r = run_cache_level(*config_, *image_, *stream_, taps);
  ASSERT_EQ(r.levels.size(), 2u);
  EXPECT_EQ(r.levels[0].name, "l1");
  EXPECT_EQ(r.levels[1].name, "l2");
  EXPECT_GT(r.first_level_hit_rate().value, 0.0);
  EXPECT_LE(r.first_level_hit_rate().value, 1.0);
  EXPECT_GT(r.dram_bytes.value, 0.0) << "cold misses at least";
  EXPECT_GT(r.cycles.value, 0.0);
  double largest = 0;
  for (const auto& [name, cycles] : bounds.bounds) largest = std::max(largest, cycles);
  EXPECT_GE(r.cycles.value, largest) << "the estimate is at least the binding bound";
  EXPECT_NE(r.time_model.find(bounds.bound), std::string::npos) << r.time_model;
}

// The L2's references, in the order the walk sends them.
struct RecordedOrder : LevelReferenceSink {
  void reference(uint32_t, uint64_t addr, LevelReference kind) override {
    order.push_back(addr * 4 + uint64_t(kind));
  }
  std::vector<uint64_t> order;
};

TEST_F(FidelityLevels, CacheLevelStepsRaysInTheOrderOfTheirClocks) {
  auto order = [&](uint32_t dram_latency) {
    HwConfig c = *config_;
    c.dram_model = DramModel::Simple;
    c.dram.latency = dram_latency;
    RecordedOrder sink;
    CacheLevelTaps taps;
    taps.sink = &sink;
    taps.tapped = 1;
    run_cache_level(c, *image_, *stream_, taps);
    return sink.order;
  };
  std::vector<uint64_t> fast = order(10), slow = order(100000);
  EXPECT_EQ(fast, order(10)) << "the same clocks give the same order";
  // A ray that missed to DRAM steps again later when DRAM is slower; round-robin steps would
  // not depend on latency at all.
  EXPECT_NE(fast, slow);
}

TEST_F(FidelityLevels, WindowsLandNearTheFullModel) {
  FidelityResult full = run_level_in_child({FidelityLevel::Cycle, {}}, *config_, *image_, *stream_);
  LevelRequest sampled{FidelityLevel::Sampled, {}};
  sampled.sampling.method = SampleMethod::Windows;
  sampled.sampling.rate = 4;
  sampled.sampling.window_rays = 1024;
  FidelityResult s = run_level_in_child(sampled, *config_, *image_, *stream_);
  EXPECT_EQ(s.rays, full.rays) << "estimates are for the whole stream";
  EXPECT_LT(s.simulated_rays, full.rays * 3 / 4) << "only the windows and warm-ups are simulated";
  EXPECT_GT(s.cycles.ci95, 0.0) << "an interval from the strata";
  EXPECT_NEAR(s.cycles.value / full.cycles.value, 1.0, 0.15) << "cycles within 15%";
  EXPECT_NEAR(s.first_level_hit_rate().value, full.first_level_hit_rate().value, 0.05)
      << "L1 hit rate within 5 pp";
  EXPECT_NEAR(s.nodes_per_ray.value / full.nodes_per_ray.value, 1.0, 0.1);
  EXPECT_EQ(s.sample_method, "windows");
}

TEST(ScaleModel, SharesTheMachineByTheRate) {
  HwConfig full = load_hw_config("", {"rt.count=32", "dispatch.rays_per_cycle=32",
                                      "dram.bytes_per_cycle=448", "dram.queue_depth=512"});
  ScaleModel m = scale_model(full, 8);
  EXPECT_EQ(m.config.rt_units, 4u);
  EXPECT_DOUBLE_EQ(m.machine_share, 0.125);
  EXPECT_DOUBLE_EQ(m.config.dispatch.rays_per_cycle, 4.0);
  EXPECT_DOUBLE_EQ(m.config.dram.bytes_per_cycle, 56.0);
  EXPECT_EQ(m.config.dram.queue_depth, 64u);
  EXPECT_EQ(last_level(m.config).cache.mshrs, last_level(full).cache.mshrs / 8);
  EXPECT_EQ(last_level(m.config).cache.size_bytes, last_level(full).cache.size_bytes)
      << "the L2 keeps its size";
  EXPECT_EQ(first_level(m.config).cache.size_bytes, first_level(full).cache.size_bytes);
  ScaleModel one = scale_model(full, 64);
  EXPECT_EQ(one.config.rt_units, 1u);
  EXPECT_DOUBLE_EQ(one.machine_share, 1.0 / 32);
  EXPECT_EQ(scale_model(full, 20).config.rt_units, 2u) << "32 / 20 units, to the nearest";
}

TEST(ScaleModel, WarpsArriveAsAUnitOfTheFullMachineGetsThem) {
  // Rate 4 on 32 units: 8 scaled units and each warp with odds 8 in 32, so the gaps between
  // chosen warps are geometric, as the dynamic dispatcher's are (a quarter of them directly
  // follow the one before), not a fixed 4.
  std::vector<uint64_t> quarter = scale_model_warps(40000, 4, 32, 7);
  EXPECT_NEAR(double(quarter.size()), 10000.0, 300.0);
  size_t adjacent = 0;
  for (size_t i = 1; i < quarter.size(); ++i) adjacent += quarter[i] == quarter[i - 1] + 1;
  EXPECT_NEAR(double(adjacent) / double(quarter.size()), 0.25, 0.02);
  EXPECT_EQ(quarter, scale_model_warps(40000, 4, 32, 7)) << "the seed decides";
  EXPECT_NE(quarter, scale_model_warps(40000, 4, 32, 8));
  // 20 on 32 units: 2 units, each warp with odds 2 in 32, so each unit gets 1 in 32 as a unit
  // of the full machine does (a sixteenth of the stream, not a twentieth).
  EXPECT_NEAR(double(scale_model_warps(40000, 20, 32, 1).size()), 2500.0, 200.0);
  // 64 on 4 units: within 1 block of kBlockWarps x 4 warps in 16, a quarter of the warps.
  uint64_t block = kBlockWarps * 4;
  std::vector<uint64_t> blocks = scale_model_warps(block * 16 * 20, 64, 4, 0);
  EXPECT_NEAR(double(blocks.size()), 20.0 * kBlockWarps, 4.0 * std::sqrt(20.0 * kBlockWarps));
  for (uint64_t w : blocks) ASSERT_EQ(w / block % 16, 0u) << w << " lies outside block 0 of 16";
  std::vector<uint64_t> other = scale_model_warps(block * 16 * 20, 64, 4, 45);
  for (uint64_t w : other) ASSERT_EQ(w / block % 16, 5u) << "the seed picks the block";
}

TEST_F(FidelityLevels, ScaleModelLandsNearTheFullModel) {
  FidelityResult full = run_level_in_child({FidelityLevel::Cycle, {}}, *config_, *image_, *stream_);
  LevelRequest scaled{FidelityLevel::Sampled, {}};
  scaled.sampling.rate = 4;
  FidelityResult s = run_level_in_child(scaled, *config_, *image_, *stream_);
  EXPECT_EQ(s.sample_method, "scale-model");
  EXPECT_EQ(s.rays, full.rays) << "estimates are for the whole stream";
  uint32_t warp = config_->rt.warp_size;
  double warps = double(full.rays) / warp, spread = 4 * std::sqrt(warps * 0.25 * 0.75) * warp;
  EXPECT_NEAR(double(s.simulated_rays), full.rays / 4.0, spread) << "each warp with odds 1 in 4";
  EXPECT_EQ(s.strata, (s.simulated_rays + warp - 1) / warp) << "one unit per warp";
  EXPECT_GT(s.cycles.ci95, 0.0);
  EXPECT_NEAR(s.cycles.value / full.cycles.value, 1.0, 0.03) << "cycles within 3%";
  EXPECT_NEAR(s.first_level_hit_rate().value, full.first_level_hit_rate().value, 0.02)
      << "L1 hit rate within 2 pp";
  EXPECT_NEAR(s.nodes_per_ray.value / full.nodes_per_ray.value, 1.0, 0.02);
  // The scene fits the L2, so nearly every DRAM byte is a cold miss, paid once however many
  // warps run; scaling them by the rate would read about 4x.
  EXPECT_NEAR(s.dram_bytes.value / full.dram_bytes.value, 1.0, 0.25);
  EXPECT_EQ(s.caveat, "") << "4 x the sampled warps' blocks fit the L2: no capacity bias";

  LevelRequest again = scaled, other = scaled;
  other.sampling.seed = 2;
  FidelityResult same = run_level_in_child(again, *config_, *image_, *stream_);
  FidelityResult moved = run_level_in_child(other, *config_, *image_, *stream_);
  EXPECT_EQ(same.cycles.value, s.cycles.value) << "same seed, same warps, same result";
  EXPECT_NE(moved.cycles.value, s.cycles.value) << "another seed samples other warps";
}

// With an L2 the stream's nodes overflow, most DRAM bytes are capacity misses that the other
// units' traffic causes: the plain scale model, whose L2 sees only its own units, reads them far
// too low; warmed, its L2 sees every unit's reads and its count of fetches lands near.
TEST_F(FidelityLevels, WarmedScaleModelCountsTheCapacityMissesOfTheWholeMachine) {
  HwConfig small = *config_;
  last_level(small).cache.size_bytes =
      192 * 1024;  // the stream's nodes overflow it: 94% of reads hit
  ASSERT_EQ(hw_config_problem(small), "");
  FidelityResult full = run_level_in_child({FidelityLevel::Cycle, {}}, small, *image_, *stream_);
  LevelRequest plain{FidelityLevel::Sampled, {}}, warmed = plain;
  plain.sampling.rate = warmed.sampling.rate = 8;
  warmed.sampling.method = SampleMethod::Warmed;
  FidelityResult p = run_level_in_child(plain, small, *image_, *stream_);
  FidelityResult w = run_level_in_child(warmed, small, *image_, *stream_);
  EXPECT_EQ(w.sample_method, "warmed");
  EXPECT_NE(w.time_model.find("warming memory.l2"), std::string::npos) << w.time_model;
  EXPECT_EQ(w.simulated_rays, p.simulated_rays) << "the same warps simulated";
  double p_error = p.dram_bytes.value / full.dram_bytes.value - 1;
  double w_error = w.dram_bytes.value / full.dram_bytes.value - 1;
  EXPECT_LT(p_error, -0.08) << "the plain scale model misses capacity misses (measured -12%)";
  EXPECT_NE(p.caveat.find("may read low"), std::string::npos) << "and says so: " << p.caveat;
  EXPECT_EQ(w.caveat, "") << "warmed, every unit's reads reach the L2";
  EXPECT_NEAR(w_error, 0.0, 0.03) << "warmed: DRAM bytes within 3% (measured -1.0%)";
  double w_l2 = w.last_level_hit_rate().value, p_l2 = p.last_level_hit_rate().value;
  double full_l2 = full.last_level_hit_rate().value;
  EXPECT_NEAR(w_l2, full_l2, 0.005) << "warmed: within 0.5 pp";
  EXPECT_GT(std::abs(p_l2 - full_l2), std::abs(w_l2 - full_l2));
  EXPECT_NEAR(w.cycles.value / full.cycles.value, 1.0, 0.03) << "cycles within 3%";
}

TEST_F(FidelityLevels, ResultsSurviveAJsonRoundTrip) {
  FidelityResult r = run_cache_level(*config_, *image_, *stream_);
  r.caveat = "L2 and DRAM figures may read low";
  FidelityResult back = FidelityResult::from_json(nlohmann::json::parse(r.to_json().dump()));
  EXPECT_EQ(back.to_json(), r.to_json());
}

}  // namespace
}  // namespace rtsim
