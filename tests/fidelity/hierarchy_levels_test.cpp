// The faster fidelity levels and the curve on hierarchies other than an L1 and one L2
// (configs/examples/four-levels.toml: l0 per unit, l1 per group of 4, sliced l2, victim-filled
// ic; a one-level and a three-level machine): the cache level's counts per level against the
// cycle model's, the scale model against the full model, and the curve of any level against the
// cache level's counts at the configured size. Timed levels run in forked children.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "model/config/hw_config.h"
#include "model/fidelity/cache_curve.h"
#include "model/fidelity/cache_level.h"
#include "model/fidelity/level_runner.h"
#include "model/fidelity/scaled_level.h"
#include "model/mem/stack_distance.h"
#include "model/sc/fork_run.h"
#include "model/sc/rt_simulator.h"
#include "model/sched/ray_source.h"
#include "model/sched/stats_registry.h"
#include "tests/fidelity/fidelity_test_util.h"
#include "tests/temp_dir.h"
#include "traces/error.h"

namespace rtsim {
namespace {

const std::string kFourLevels =
    std::string(RTSIM_SOURCE_DIR) + "/configs/examples/four-levels.toml";
// The example with its l2 and ic cut to a size the test scene's BVH overflows, so that the l2
// evicts into the ic and the ic misses too.
const std::vector<std::string> kSmall = {"memory.l2.size_bytes=65536",
                                         "memory.ic.size_bytes=196608"};

std::vector<std::string> with_small(std::vector<std::string> sets) {
  sets.insert(sets.end(), kSmall.begin(), kSmall.end());
  return sets;
}

// A level's counters as a run counted them.
struct LevelCounts {
  uint64_t accesses = 0, hits = 0, misses = 0, merges = 0, victim_fills = 0, victims = 0;
};

// The cycle model's counters of every level (mem.NAME.*), in a forked child.
std::vector<LevelCounts> cycle_counts(const HwConfig& config, BvhView image,
                                      const std::string& stream) {
  std::string text = run_in_child([&] {
    RayStreamReader reader(stream);
    StreamRaySource source(reader);
    RtSimulator sim(config, image, source);
    sim.run();
    StatsRegistry stats;
    sim.report(stats);
    nlohmann::json out = nlohmann::json::array();
    for (const MemoryLevelConfig& level : config.memory) {
      std::string p = "mem." + level.name + ".";
      out.push_back({stats.value(p + "accesses"), stats.value(p + "hits"),
                     stats.value(p + "misses"), stats.value(p + "mshr_merges"),
                     stats.value(p + "victim_fills")});
    }
    return out.dump();
  });
  std::vector<LevelCounts> counts;
  for (const auto& l : nlohmann::json::parse(text))
    counts.push_back({uint64_t(l[0].get<double>()), uint64_t(l[1].get<double>()),
                      uint64_t(l[2].get<double>()), uint64_t(l[3].get<double>()),
                      uint64_t(l[4].get<double>())});
  return counts;
}

std::vector<LevelCounts> cache_counts(const HwConfig& config, BvhView image,
                                      const std::string& stream) {
  std::vector<CacheStats> stats;
  CacheLevelTaps taps;
  taps.levels = &stats;
  run_cache_level(config, image, stream, taps);
  std::vector<LevelCounts> counts;
  for (const CacheStats& s : stats)
    counts.push_back({s.accesses, s.hits, s.misses, s.mshr_merges, s.victim_fills, s.victims});
  return counts;
}

class HierarchyLevels : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    stream_ = new std::string(test::small_stream("grid:2000", 8000, 11));
    scene_ = new Scene(load_scene("grid:2000"));
    config_ = new HwConfig(load_hw_config(kFourLevels, kSmall));
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
std::string* HierarchyLevels::stream_;
Scene* HierarchyLevels::scene_;
HwConfig* HierarchyLevels::config_;
BvhImage* HierarchyLevels::image_;

// With one ray in flight on the machine, each read of the cycle model completes before the next
// is made, so its caches see the walk's references in the walk's order and nothing merges: every
// level's counts, victim fills included, must be the cache level's exactly.
TEST_F(HierarchyLevels, CacheLevelCountsEveryLevelAsTheCycleModelWithOneRayInFlight) {
  HwConfig one = load_hw_config(kFourLevels, with_small({"rt.count=1", "rt.warps=1",
                                                         "rt.warp_size=1", "rt.stack.entries=64"}));
  std::vector<LevelCounts> cache = cache_counts(one, *image_, *stream_);
  std::vector<LevelCounts> cycle = cycle_counts(one, *image_, *stream_);
  ASSERT_EQ(cache.size(), 4u);
  ASSERT_EQ(cycle.size(), 4u);
  for (size_t i = 0; i < 4; ++i) {
    SCOPED_TRACE("level " + one.memory[i].name);
    EXPECT_EQ(cycle[i].merges, 0u) << "one ray in flight: nothing to merge into";
    EXPECT_EQ(cache[i].accesses, cycle[i].accesses);
    EXPECT_EQ(cache[i].hits, cycle[i].hits);
    EXPECT_EQ(cache[i].misses, cycle[i].misses);
    EXPECT_EQ(cache[i].victim_fills, cycle[i].victim_fills);
  }
  EXPECT_GT(cache[3].victim_fills, 0u) << "the l2's evictions fill the ic";
  EXPECT_GT(cache[3].misses, 0u) << "and the ic misses";
}

// On the whole machine (8 units, 128 rays each in flight) the cycle model interleaves the units'
// reads by time and merges reads into misses in flight (on this short stream, most first reads of
// the BVH's top: its l0 hit rate is about half the walk's), which the walk, reading one block at a
// time, counts as hits. So each level's share of reads served without a fetch (hits and merges)
// is compared: within 8 points at every level. The order of the units' reads still differs, and
// with an l2 the BVH overflows, it decides which of the l2 and the ic keeps a line (measured: the
// l2 serves 6.5 points fewer than in the cycle model, the ic 6.4 more).
TEST_F(HierarchyLevels, CacheLevelServesReadsAsTheCycleModelOnTheWholeMachine) {
  std::vector<LevelCounts> cache = cache_counts(*config_, *image_, *stream_);
  std::vector<LevelCounts> cycle = cycle_counts(*config_, *image_, *stream_);
  FidelityResult named = run_cache_level(*config_, *image_, *stream_);
  ASSERT_EQ(named.levels.size(), 4u);
  for (size_t i = 0; i < 4; ++i) {
    SCOPED_TRACE("level " + config_->memory[i].name);
    EXPECT_EQ(named.levels[i].name, config_->memory[i].name);
    EXPECT_DOUBLE_EQ(named.levels[i].hit_rate.value,
                     double(cache[i].hits) / double(cache[i].accesses));
    EXPECT_EQ(cache[i].merges, 0u) << "the walk's reads find the caches idle";
    double walk = double(cache[i].hits) / double(cache[i].accesses);
    double served = double(cycle[i].hits + cycle[i].merges) / double(cycle[i].accesses);
    EXPECT_NEAR(walk, served, 0.08);
  }
}

// A one-level machine (the unit's cache in front of DRAM) and a three-level one (unit, group of
// 2, shared), at the cache level and the scale model against the full model.
TEST_F(HierarchyLevels, OneAndThreeLevelsRunAtTheCacheLevelAndTheScaleModel) {
  test::TempDir dir;
  // The simple DRAM: with the banked one, whose channels the scale model scales, a DRAM-bound
  // machine's scale model reads cycles high (one.toml: +23% at 1/2, +31% at 1/4; with the simple
  // DRAM +1%; model/fidelity/README.md, known limitations).
  std::string one = dir.write("one.toml", R"([rt]
count = 4
[dram]
model = "simple"
[[memory.level]]
name = "c0"
scope = "unit"
size_bytes = 16384
)");
  std::string three = dir.write("three.toml", R"([rt]
count = 8
[dram]
model = "simple"
[[memory.level]]
name = "c0"
size_bytes = 8192
[[memory.level]]
name = "c1"
scope = "group:2"
size_bytes = 32768
link_latency = 8
[[memory.level]]
name = "c2"
scope = "shared"
slices = 4
size_bytes = 262144
)");
  std::string stream = test::small_stream("grid:2000", 40000, 13);
  for (const std::string& file : {one, three}) {
    HwConfig config = load_hw_config(file);
    SCOPED_TRACE(file);
    FidelityResult cache = run_cache_level(config, *image_, stream);
    std::vector<LevelCounts> walk = cache_counts(config, *image_, stream);
    std::vector<LevelCounts> timed = cycle_counts(config, *image_, stream);
    FidelityResult full = run_level_in_child({FidelityLevel::Cycle, {}}, config, *image_, stream);
    LevelRequest scaled{FidelityLevel::Sampled, {}};
    scaled.sampling.rate = 4;
    FidelityResult s = run_level_in_child(scaled, config, *image_, stream);
    ASSERT_EQ(cache.levels.size(), config.memory.size());
    ASSERT_EQ(s.levels.size(), config.memory.size());
    for (size_t i = 0; i < config.memory.size(); ++i) {
      SCOPED_TRACE("level " + config.memory[i].name);
      EXPECT_EQ(cache.levels[i].name, config.memory[i].name);
      EXPECT_EQ(s.levels[i].name, config.memory[i].name);
      // The walk counts the cycle model's merges as hits (above).
      EXPECT_NEAR(double(walk[i].hits) / double(walk[i].accesses),
                  double(timed[i].hits + timed[i].merges) / double(timed[i].accesses), 0.05);
      EXPECT_NEAR(s.levels[i].hit_rate.value, full.levels[i].hit_rate.value, 0.03);
    }
    EXPECT_GT(cache.cycles.value, 0.0);
    EXPECT_NEAR(s.cycles.value / full.cycles.value, 1.0, 0.05) << "scale model: cycles within 5%";
    EXPECT_NEAR(s.dram_bytes.value / full.dram_bytes.value, 1.0, 0.25);
  }
  std::filesystem::remove(stream);
}

// The scale model of four-levels at 1/4: 2 of 8 units, so the group level's one instance serves
// 2 of its 4 units and the shared levels 2 of 8; their MSHRs scale with that, sizes stay.
TEST(ScaleModelLevels, ScalesEachLevelByTheUnitsAnInstanceServes) {
  HwConfig full = load_hw_config(kFourLevels);
  ScaleModel m = scale_model(full, 4);
  ASSERT_EQ(m.config.rt_units, 2u);
  EXPECT_EQ(m.level_share, (std::vector<double>{1.0, 0.5, 0.25, 0.25}));
  EXPECT_EQ(m.first_shared, 2u) << "the first shared level pays DRAM's first reads";
  EXPECT_EQ(m.config.memory[1].cache.mshrs, full.memory[1].cache.mshrs / 2);
  EXPECT_EQ(m.config.memory[2].cache.mshrs, full.memory[2].cache.mshrs / 4);
  EXPECT_EQ(m.config.memory[0].cache.mshrs, full.memory[0].cache.mshrs);
  for (size_t i = 0; i < 4; ++i)
    EXPECT_EQ(m.config.memory[i].cache.size_bytes, full.memory[i].cache.size_bytes);
  ScaleModel half = scale_model(full, 2);  // 4 units: one full group, as the full machine's
  EXPECT_EQ(half.level_share[1], 1.0);
  EXPECT_EQ(half.config.memory[1].cache.mshrs, full.memory[1].cache.mshrs);
}

// The scale model of the four-level example at 1/2 and 1/4 (4 and 2 of 8 units: the group level
// full, then half) against the full model: l0, l1 and ic hit rates, DRAM bytes (measured: exact)
// and cycles (-3.2%, -0.7%). The levels below the first shared one see its first fetches once:
// without that the ic's hit rate, all cold misses in the full model, read 77% at 1/4 on a Sponza
// frame. Not checked: the l2's hit rate, which reads high here (52% at 1/2, 77% at 1/4, against
// 24%; model/fidelity/README.md, known limitations).
TEST_F(HierarchyLevels, ScaleModelOfFourLevelsLandsNearTheFullModel) {
  std::string stream = test::small_stream("grid:2000", 40000, 17);
  HwConfig config = load_hw_config(kFourLevels);
  FidelityResult full = run_level_in_child({FidelityLevel::Cycle, {}}, config, *image_, stream);
  for (uint32_t rate : {2u, 4u}) {
    SCOPED_TRACE("rate " + std::to_string(rate));
    LevelRequest scaled{FidelityLevel::Sampled, {}};
    scaled.sampling.rate = rate;
    FidelityResult s = run_level_in_child(scaled, config, *image_, stream);
    ASSERT_EQ(s.levels.size(), 4u);
    for (size_t i : {0, 1, 3})
      EXPECT_NEAR(s.levels[i].hit_rate.value, full.levels[i].hit_rate.value, 0.05)
          << config.memory[i].name << ": " << s.levels[i].hit_rate.value << " against "
          << full.levels[i].hit_rate.value;
    EXPECT_NEAR(s.dram_bytes.value / full.dram_bytes.value, 1.0, 0.05);
    EXPECT_NEAR(s.cycles.value / full.cycles.value, 1.0, 0.05);
  }
  std::filesystem::remove(stream);
}

TEST_F(HierarchyLevels, WarmedRefusesOtherThanTwoLevelsInOneLine) {
  LevelRequest warmed{FidelityLevel::Sampled, {}};
  warmed.sampling.method = SampleMethod::Warmed;
  try {
    run_level(warmed, *config_, *image_, *stream_);
    FAIL() << "warmed ran on four levels";
  } catch (const InputError& e) {
    std::string what = e.what();
    EXPECT_NE(what.find("--sample-method warmed"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

// The curve of any level taps what arrives there: at the configured size its point is the cache
// level's own counts of that level (the walk runs the level at the smallest capacity asked for).
TEST_F(HierarchyLevels, CurveOfEachLevelAtItsSizeIsTheCacheLevels) {
  std::vector<LevelCounts> cache = cache_counts(*config_, *image_, *stream_);
  for (uint32_t i = 0; i < config_->memory.size(); ++i) {
    const MemoryLevelConfig& level = config_->memory[i];
    SCOPED_TRACE(level.name);
    CurveRequest request{
        {level.cache.size_bytes, 2 * level.cache.size_bytes}, {level.cache.ways}, 1, level.name};
    ASSERT_EQ(curve_request_problem(*config_, request), "");
    CacheCurve curve = run_cache_curve(*config_, *image_, *stream_, request);
    EXPECT_EQ(curve.level, level.name);
    EXPECT_EQ(curve.instances, level_instances(level, config_->rt_units));
    EXPECT_EQ(curve.reads, cache[i].accesses) << "every read arriving at the level";
    EXPECT_EQ(curve.points[0].misses, double(cache[i].misses));
    EXPECT_LE(curve.points[1].misses, curve.points[0].misses);
    if (level.fill == LevelFill::Victim) {
      EXPECT_EQ(curve.fills, cache[i - 1].victims) << "every clean line the level above evicts";
      EXPECT_GE(curve.fills, cache[i].victim_fills) << "those it did not hold already";
    }
  }
  // The default is the level above DRAM.
  CurveRequest last{{config_->memory[3].cache.size_bytes}, {16}, 1, ""};
  EXPECT_EQ(curve_level(*config_, last), 3u);
  last.level = "nope";
  EXPECT_THROW(curve_level(*config_, last), InputError);
}

// Tamper check: the victim level's reads and writes counted with an LRU stack, as a level filled
// by its misses is counted (its read misses taking lines, the l2's victims left out), do not give
// the cache level's count there; the equality of the test above catches such a curve.
TEST_F(HierarchyLevels, TamperedVictimCurveByStacksMissesTheCacheLevelsCount) {
  std::vector<LevelCounts> cache = cache_counts(*config_, *image_, *stream_);
  struct Forward : LevelReferenceSink {
    std::unique_ptr<LruStackSets> stack;
    void reference(uint32_t, uint64_t addr, LevelReference kind) override {
      if (kind != LevelReference::Fill) stack->reference(addr, kind == LevelReference::Write);
    }
  } forward;
  const MemoryLevelConfig& ic = config_->memory[3];
  forward.stack = std::make_unique<LruStackSets>(
      L2Sets{ic.cache.line_bytes, block_bytes(ic.cache), ic.slices,
             ic.cache.size_bytes / (uint64_t(ic.cache.line_bytes) * ic.cache.ways * ic.slices)},
      ic.cache.ways);
  CacheLevelTaps taps;
  taps.sink = &forward;
  taps.tapped = 3;
  run_cache_level(*config_, *image_, *stream_, taps);  // the true victim level's references
  forward.stack->finish();
  EXPECT_NE(forward.stack->read_misses(ic.cache.ways), cache[3].misses)
      << "stacks would have to stand for a victim level for this to hold";
}

}  // namespace
}  // namespace rtsim
