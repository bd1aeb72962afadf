// The cache curve (model/fidelity/cache_curve.h): on a small stream its point at the walk's L2
// (the smallest capacity) is the cache level's own L2 there, count for count, and the curve never
// rises with capacity; the knee and the interpolated cycles follow their rules on hand-made points.
#include "model/fidelity/cache_curve.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "model/bvh/bvh_image.h"
#include "model/fidelity/cache_level.h"
#include "model/mem/memory_level.h"
#include "tests/fidelity/fidelity_test_util.h"

namespace rtsim {
namespace {

TEST(CacheCurve, PointAtTheWalksL2IsTheCacheLevelsL2) {
  std::string stream = test::small_stream("grid:2000", 20000);
  Scene scene = load_scene("grid:2000");
  // One slice, as the cache level's L2 has; small enough that capacity misses matter.
  HwConfig config = load_hw_config(
      "", {"l2.slices=1", "l2.size_bytes=16384", "l2.sector_bytes=32", "rt.l1.size_bytes=4096"});
  BvhImage image = build_bvh_image(scene.mesh, config.bvh);
  // The walk's L2 is the smallest capacity: here the configured one.
  CurveRequest request{{16384, 32768, 65536, 131072, 262144}, {last_level(config).cache.ways}, 1};
  ASSERT_EQ(curve_request_problem(config, request), "");
  CacheCurve curve = run_cache_curve(config, image, stream, request);
  FidelityResult level = run_cache_level(config, image, stream);
  std::filesystem::remove(stream);

  ASSERT_EQ(curve.points.size(), 5u);
  const CurvePoint& at_config = curve.points[0];
  ASSERT_EQ(at_config.capacity, 16384u);
  // The walk's L2 never merges (its reads are far apart), so its misses are accesses - hits.
  EXPECT_DOUBLE_EQ(at_config.misses * curve.block_bytes, level.dram_bytes.value);
  EXPECT_NEAR(1 - at_config.miss_ratio, level.last_level_hit_rate().value, 1e-12);
  EXPECT_GT(at_config.miss_ratio, 0.05) << "the stream should not fit 16 KB";
  for (size_t i = 1; i < curve.points.size(); ++i)
    EXPECT_LE(curve.points[i].dram_bytes, curve.points[i - 1].dram_bytes) << i;
  EXPECT_EQ(curve.rays, 20000u);
}

// Counts the L2 references to the shading region.
struct ShadingReferences : LevelReferenceSink {
  void reference(uint32_t, uint64_t addr, LevelReference) override {
    count += addr >= kShadingBase && addr < kTextureBase;
  }
  uint64_t count = 0;
};

TEST(CacheCurve, HitShadingReadsJoinTheL2Stream) {
  std::string stream = test::small_stream("grid:2000", 20000);
  Scene scene = load_scene("grid:2000");
  auto shading = [&](const std::string& model) {
    HwConfig config = load_hw_config("", {"shader.model=" + model});
    BvhImage image = build_bvh_image(scene.mesh, config.bvh);
    EXPECT_EQ(curve_request_problem(config, {{65536}, {last_level(config).cache.ways}, 1}), "");
    ShadingReferences sink;
    CacheLevelTaps taps;
    taps.sink = &sink;
    taps.tapped = 1;
    FidelityResult r = run_cache_level(config, image, stream, taps);
    return std::make_pair(sink.count, r.rays);
  };
  auto [none, rays] = shading("none");
  uint64_t simt = shading("simt").first;
  std::filesystem::remove(stream);
  EXPECT_EQ(none, 0u);
  // Each hit reads its pixel's 64 bytes (one L1 line) when its warp is done; the L1 sends on
  // those no ray of the frame brought in before.
  EXPECT_GT(simt, 0u);
  EXPECT_LE(simt, rays);
}

TEST(CacheCurve, RefusesCapacitiesWithoutWholeSets) {
  HwConfig config = load_hw_config("", {"l2.slices=4", "l2.line_bytes=128", "l2.ways=16"});
  EXPECT_EQ(curve_request_problem(config, {{8192 * 4}, {16}, 1}), "");
  EXPECT_NE(curve_request_problem(config, {{8192 * 3 + 128}, {16}, 1}), "");
  EXPECT_NE(curve_request_problem(config, {{4096}, {16}, 1}), "");       // under one set a slice
  EXPECT_NE(curve_request_problem(config, {{8192 * 4}, {16}, 32}), "");  // 16 sets, 1 in 32
}

// Points of 1, 2, 4, 8 and 16 KB with DRAM bytes 100, 50, 10, 8, 7.
CacheCurve hand_made() {
  CacheCurve c;
  double dram[] = {100, 50, 10, 8, 7};
  for (int i = 0; i < 5; ++i) {
    CurvePoint p;
    p.capacity = 1024u << i;
    p.ways = 4;
    p.dram_bytes = dram[i];
    c.points.push_back(p);
  }
  return c;
}

TEST(CacheCurve, KneeIsFarthestBelowTheChord) {
  CacheCurve c = hand_made();
  // Normalised, 1 - x - y is 0, 0.288, 0.468, 0.239, 0: the knee is 4 KB.
  EXPECT_EQ(curve_knee(c, {0, 1, 2, 3, 4}), 2u);
  EXPECT_EQ(curve_knee(c, {0, 1}), 0u);  // too few points: the first
}

TEST(CacheCurve, CyclesInterpolateAlongDramBytes) {
  CacheCurve c = hand_made();
  for (auto [i, cycles] : {std::pair{0, 1000.0}, {2, 600.0}, {4, 500.0}}) {
    c.points[i].has_cycle_run = true;
    c.points[i].cycle_run.cycles = cycles;
  }
  fill_cycles(c, {0, 1, 2, 3, 4});
  using From = CurvePoint::Cycles;
  EXPECT_EQ(c.points[0].cycles_from, From::Simulated);
  EXPECT_EQ(c.points[1].cycles_from, From::Interpolated);
  EXPECT_NEAR(c.points[1].cycles, 1000 - 400 * 50.0 / 90, 1e-9);  // 5/9 of the way to 4 KB
  EXPECT_NEAR(c.points[3].cycles, 600 - 100 * 2.0 / 3, 1e-9);
  ASSERT_TRUE(c.points[2].has_check);  // 4 KB from 1 KB and 16 KB, as if not simulated
  EXPECT_NEAR(c.points[2].cycles_check, 1000 - 500 * 90.0 / 93, 1e-9);
  EXPECT_FALSE(c.points[0].has_check);

  CacheCurve two = hand_made();
  for (auto [i, cycles] : {std::pair{0, 1000.0}, {2, 600.0}}) {
    two.points[i].has_cycle_run = true;
    two.points[i].cycle_run.cycles = cycles;
  }
  fill_cycles(two, {0, 1, 2, 3, 4});
  EXPECT_EQ(two.points[3].cycles_from, From::Extrapolated);
  EXPECT_NEAR(two.points[3].cycles, 1000 - 400 * 92.0 / 90, 1e-9);
}

}  // namespace
}  // namespace rtsim
