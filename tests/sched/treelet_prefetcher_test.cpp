// Treelet prefetching: each treelet's footprint, when the prefetcher fires, and RT units that
// prefetch (answers unchanged, every prefetch a treelet's footprint).
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "model/sched/rt_core.h"
#include "model/sched/treelet_prefetcher.h"
#include "model/sched/treelet_scheduler.h"
#include "tests/model/model_test_util.h"
#include "tests/sched/drive_cores.h"
#include "tests/sched/mock_neighbours.h"

namespace rtsim {
namespace {

BvhImage small_image(const TriangleMesh& mesh) {
  BvhConfig bvh;
  bvh.width = 4;
  bvh.treelet_bytes = 1024;
  return build_bvh_image(mesh, bvh);
}

TEST(TreeletFootprints, HoldEachNodeAndEachLeafTriangleInItsTreeletOnce) {
  TriangleMesh mesh = test::random_soup(3000, 0.6f, 11);
  BvhImage image = small_image(mesh);
  std::vector<std::vector<ByteRange>> footprints = treelet_footprints(image);
  ASSERT_EQ(footprints.size(), image.treelets.count);
  // Every byte of the image is in exactly one treelet: the node it belongs to's.
  uint64_t total = 0;
  std::set<uint64_t> seen;
  for (uint32_t t = 0; t < footprints.size(); ++t)
    for (const ByteRange& r : footprints[t]) {
      total += r.bytes;
      for (uint64_t a = r.addr; a < r.addr + r.bytes; a += 4) ASSERT_TRUE(seen.insert(a).second);
      if (r.addr < image.triangle_base) {
        auto position = uint32_t((r.addr - image.node_base) / image.node_stride);
        EXPECT_EQ(image.node_treelet[position], t);
      }
    }
  EXPECT_EQ(total, uint64_t(image.node_count) * image.node_size +
                       uint64_t(image.triangle_count) * image.triangle_stride);
}

TEST(TreeletPrefetcher, FirstVisitSkipsTheTreeletsItPrefetchedLately) {
  std::vector<std::vector<ByteRange>> footprints(10, {{0x1000, 256}});
  PrefetchConfig c;
  c.trigger = PrefetchTrigger::FirstVisit;
  c.recent = 2;
  TreeletPrefetcher p(c, &footprints);
  EXPECT_EQ(p.on_node(5).size(), 1u);
  EXPECT_TRUE(p.on_node(5).empty());
  EXPECT_EQ(p.on_node(6).size(), 1u);
  EXPECT_EQ(p.on_node(7).size(), 1u);
  EXPECT_EQ(p.on_node(5).size(), 1u) << "5 left the unit's memory of two treelets";
  EXPECT_TRUE(p.on_batch(5, 1000).empty()) << "not the batch trigger";
  EXPECT_EQ(p.stats().treelets, 4u);
  EXPECT_EQ(p.stats().skipped, 1u);
  EXPECT_EQ(p.stats().bytes, 4u * 256);
}

TEST(TreeletPrefetcher, BatchFiresFromItsThresholdAndMaxBytesCutsTheFootprint) {
  std::vector<std::vector<ByteRange>> footprints(3, {{0x1000, 256}, {0x9000, 200}});
  PrefetchConfig c;
  c.trigger = PrefetchTrigger::Batch;
  c.batch_rays = 16;
  c.max_bytes = 300;
  TreeletPrefetcher p(c, &footprints);
  EXPECT_TRUE(p.on_batch(1, 15).empty());
  const std::vector<ByteRange>& ranges = p.on_batch(1, 16);
  ASSERT_EQ(ranges.size(), 2u);
  EXPECT_EQ(ranges[0].bytes, 256u);
  EXPECT_EQ(ranges[1].addr, 0x9000u);
  EXPECT_EQ(ranges[1].bytes, 44u) << "300 bytes in all, nodes first";
  EXPECT_TRUE(p.on_node(2).empty()) << "not the first_visit trigger";
}

struct PrefetchRun {
  std::vector<test::Retired> done;
  std::vector<test::MockRayMemory::Request> prefetches;
  uint64_t treelets = 0;
};

PrefetchRun run_prefetching(const BvhImage& image, const std::vector<Ray>& rays, TraversalMode mode,
                            PrefetchTrigger trigger) {
  TraversalUnit unit(image);
  test::MockRayMemory memory(40);
  bool treelets = mode == TraversalMode::Treelet;
  test::MockSupply supply(rays, unit, treelets ? 64 : 16);
  TreeletQueueConfig tq;
  tq.max_rays = 64;
  tq.min_batch = 4;
  TreeletScheduler queues(tq, image.treelets.count, {image.node_treelet[0]}, supply.dispatcher,
                          supply.pool, 100);
  RtCoreConfig config;
  config.mode = mode;
  config.warps = 2;
  config.warp_size = 8;
  config.prefetch.trigger = trigger;
  config.prefetch.batch_rays = 4;
  TreeletFootprints footprints = treelet_footprints(image);
  RtCore core(0, config, unit, memory, &footprints);
  core.set_supply(treelets ? static_cast<RaySupply*>(&queues) : &supply.dispatcher);
  test::drive({&core});
  return {supply.listener.done, memory.prefetches, core.prefetch_stats().treelets};
}

void expect_footprints(const BvhImage& image, const PrefetchRun& run) {
  std::vector<std::vector<ByteRange>> footprints = treelet_footprints(image);
  std::set<std::pair<uint64_t, uint32_t>> ranges;
  for (const auto& f : footprints)
    for (const ByteRange& r : f) ranges.insert({r.addr, r.bytes});
  ASSERT_GT(run.treelets, 0u);
  for (const auto& p : run.prefetches) ASSERT_TRUE(ranges.count({p.addr, p.bytes}));
}

TEST(TreeletPrefetcher, DepthFirstUnitsPrefetchTreeletsOnFirstVisitWithUnchangedAnswers) {
  TriangleMesh mesh = test::random_soup(3000, 0.6f, 11);
  BvhImage image = small_image(mesh);
  std::vector<Ray> rays = sample_diffuse_rays(mesh, 400, 6);
  PrefetchRun off = run_prefetching(image, rays, TraversalMode::DepthFirst, PrefetchTrigger::None);
  PrefetchRun on =
      run_prefetching(image, rays, TraversalMode::DepthFirst, PrefetchTrigger::FirstVisit);
  EXPECT_TRUE(off.prefetches.empty());
  expect_footprints(image, on);
  ASSERT_EQ(on.done.size(), rays.size());
  for (size_t i = 0; i < rays.size(); ++i) {
    const test::Retired* a = &on.done[i];
    auto b = std::find_if(off.done.begin(), off.done.end(),
                          [&](const test::Retired& r) { return r.sequence == a->sequence; });
    ASSERT_NE(b, off.done.end());
    ASSERT_EQ(a->hit.prim, b->hit.prim) << "prefetching changes timing, never answers";
  }
}

TEST(TreeletPrefetcher, TreeletUnitsPrefetchTheTreeletOfEachLargeEnoughBatch) {
  TriangleMesh mesh = test::random_soup(3000, 0.6f, 11);
  BvhImage image = small_image(mesh);
  std::vector<Ray> rays = sample_diffuse_rays(mesh, 400, 6);
  PrefetchRun on = run_prefetching(image, rays, TraversalMode::Treelet, PrefetchTrigger::Batch);
  expect_footprints(image, on);
  EXPECT_EQ(on.done.size(), rays.size());
}

}  // namespace
}  // namespace rtsim
