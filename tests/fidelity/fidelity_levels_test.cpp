// Every fidelity level on one small stream: the functional counts are the traversal's, the
// cache level's memory figures are plausible, and the sampled level lands near the full cycle
// model with an interval. Timed levels run in forked children (SystemC elaborates once).
#include <gtest/gtest.h>

#include <filesystem>

#include "model/config/hw_config.h"
#include "model/fidelity/cache_level.h"
#include "model/fidelity/functional_level.h"
#include "model/fidelity/level_runner.h"
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
  EXPECT_FALSE(r.l1_hit_rate.known) << "nor caches";
}

TEST_F(FidelityLevels, CacheLevelHasMemoryFiguresAndARooflineTime) {
  AnalyticTime bounds;
  FidelityResult r = run_cache_level(*config_, *image_, *stream_, &bounds);
  EXPECT_GT(r.l1_hit_rate.value, 0.0);
  EXPECT_LE(r.l1_hit_rate.value, 1.0);
  EXPECT_GT(r.dram_bytes.value, 0.0) << "cold misses at least";
  EXPECT_GT(r.cycles.value, 0.0);
  double largest = 0;
  for (const auto& [name, cycles] : bounds.bounds) largest = std::max(largest, cycles);
  EXPECT_GE(r.cycles.value, largest) << "the estimate is at least the binding bound";
  EXPECT_NE(r.time_model.find(bounds.bound), std::string::npos) << r.time_model;
}

TEST_F(FidelityLevels, SampledLandsNearTheFullModel) {
  FidelityResult full = run_level_in_child({FidelityLevel::Cycle, {}}, *config_, *image_, *stream_);
  LevelRequest sampled{FidelityLevel::Sampled, {}};
  sampled.sampling.rate = 4;
  sampled.sampling.window_rays = 1024;
  FidelityResult s = run_level_in_child(sampled, *config_, *image_, *stream_);
  EXPECT_EQ(s.rays, full.rays) << "estimates are for the whole stream";
  EXPECT_LT(s.simulated_rays, full.rays * 3 / 4) << "only the windows and warm-ups are simulated";
  EXPECT_GT(s.cycles.ci95, 0.0) << "an interval from the strata";
  EXPECT_NEAR(s.cycles.value / full.cycles.value, 1.0, 0.15) << "cycles within 15%";
  EXPECT_NEAR(s.l1_hit_rate.value, full.l1_hit_rate.value, 0.05) << "L1 hit rate within 5 pp";
  EXPECT_NEAR(s.nodes_per_ray.value / full.nodes_per_ray.value, 1.0, 0.1);
}

TEST_F(FidelityLevels, ResultsSurviveAJsonRoundTrip) {
  FidelityResult r = run_cache_level(*config_, *image_, *stream_);
  FidelityResult back = FidelityResult::from_json(nlohmann::json::parse(r.to_json().dump()));
  EXPECT_EQ(back.to_json(), r.to_json());
}

}  // namespace
}  // namespace rtsim
