// RT units in every traversal mode, driven without SystemC: every timed ray's answer is the
// functional traversal's, bit for bit; packets measure SIMD efficiency; spilled stack entries
// all come back.
#include <gtest/gtest.h>

#include <cstring>

#include "model/sched/ray_buffer.h"
#include "model/sched/ray_sorter.h"
#include "model/sched/rt_core.h"
#include "model/sched/treelet_scheduler.h"
#include "tests/model/model_test_util.h"
#include "tests/sched/drive_cores.h"
#include "tests/sched/mock_neighbours.h"

namespace rtsim {
namespace {

struct Scene {
  Scene() : mesh(test::random_soup(3000, 0.6f, 11)) {
    BvhConfig bvh;
    bvh.width = 4;
    bvh.treelet_bytes = 1024;
    image = build_bvh_image(mesh, bvh);
    rays = sample_random_rays(mesh, 1500, 5);
    std::vector<Ray> diffuse = sample_diffuse_rays(mesh, 1500, 6);
    rays.insert(rays.end(), diffuse.begin(), diffuse.end());
    for (size_t i = 0; i < rays.size(); i += 3) rays[i].query = Query::AnyHit;
  }
  TriangleMesh mesh;
  BvhImage image;
  std::vector<Ray> rays;
};

bool same_bits(float a, float b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

RtCoreConfig small_config(TraversalMode mode, PacketPolicy policy = PacketPolicy::NodeFirst,
                          PacketReorderConfig reorder = {}) {
  RtCoreConfig c;
  c.mode = mode;
  c.packet_policy = policy;
  c.reorder = reorder;
  c.warps = 2;
  c.warp_size = 8;
  c.stack.entries = 2;  // small: spills happen
  return c;
}

// Runs two cores over the scene's rays and checks each answer against TraversalUnit::trace.
std::vector<test::Retired> run_mode(const Scene& scene, TraversalMode mode,
                                    RtCoreStats* stats = nullptr,
                                    PacketPolicy policy = PacketPolicy::NodeFirst,
                                    PacketReorderConfig reorder = {}) {
  TraversalUnit unit(scene.image);
  test::MockRayMemory memory0(40), memory1(60);
  bool treelets = mode == TraversalMode::Treelet;
  test::MockSupply supply(scene.rays, unit, treelets ? 64 : 32);
  TreeletQueueConfig tq;
  tq.max_rays = 64;
  tq.min_batch = 4;
  TreeletScheduler queues(tq, scene.image.treelets.count, {scene.image.node_treelet[0]},
                          supply.dispatcher, supply.pool, 100);
  RaySupply* feed = treelets ? static_cast<RaySupply*>(&queues) : &supply.dispatcher;
  RtCore core0(0, small_config(mode, policy, reorder), unit, memory0);
  RtCore core1(1, small_config(mode, policy, reorder), unit, memory1);
  core0.set_supply(feed);
  core1.set_supply(feed);
  test::drive({&core0, &core1});
  if (stats) {
    *stats = core0.stats();
    stats->spill_entries += core1.stats().spill_entries;
    stats->reorders += core1.stats().reorders;
    stats->refill_entries += core1.stats().refill_entries;
  }
  if (treelets) {
    EXPECT_GT(queues.stats().postponed, 0u) << "rays did wait in treelet queues";
  }
  return supply.listener.done;
}

void expect_functional(const Scene& scene, const std::vector<test::Retired>& done,
                       const char* mode) {
  ASSERT_EQ(done.size(), scene.rays.size()) << mode << ": every ray retired once";
  TraversalUnit unit(scene.image);
  TraversalState state;
  std::vector<bool> seen(scene.rays.size(), false);
  for (const test::Retired& r : done) {
    ASSERT_FALSE(seen[r.sequence]) << mode;
    seen[r.sequence] = true;
    const Ray& ray = scene.rays[r.sequence];
    Hit want = unit.trace(state, ray);
    ASSERT_EQ(r.hit.prim, want.prim) << mode << " ray " << r.sequence;
    ASSERT_TRUE(same_bits(r.hit.t, want.t)) << mode << " ray " << r.sequence;
    ASSERT_TRUE(same_bits(r.hit.u, want.u) && same_bits(r.hit.v, want.v)) << mode;
    ASSERT_EQ(r.counters.trav_nodes, state.counters.trav_nodes) << mode << " same path";
    ASSERT_EQ(r.counters.trav_prims, state.counters.trav_prims) << mode << " same path";
  }
}

TEST(RtCoreModes, DepthFirstAnswersEqualTheFunctionalTraversal) {
  Scene scene;
  expect_functional(scene, run_mode(scene, TraversalMode::DepthFirst), "depth_first");
}

TEST(RtCoreModes, TreeletQueueAnswersEqualTheFunctionalTraversal) {
  Scene scene;
  expect_functional(scene, run_mode(scene, TraversalMode::Treelet), "treelet");
}

TEST(RtCoreModes, PacketAnswersEqualTheFunctionalTraversal) {
  Scene scene;
  expect_functional(scene, run_mode(scene, TraversalMode::Packet), "packet");
}

TEST(RtCoreModes, MajorityPacketAnswersEqualTheFunctionalTraversal) {
  Scene scene;
  expect_functional(scene, run_mode(scene, TraversalMode::Packet, nullptr, PacketPolicy::Majority),
                    "packet majority");
}

TEST(RtCoreModes, ReorderedPacketAnswersEqualTheFunctionalTraversal) {
  Scene scene;
  RtCoreStats stats;
  PacketReorderConfig reorder{0.5, 2, 3};
  for (PacketPolicy policy : {PacketPolicy::NodeFirst, PacketPolicy::Majority}) {
    expect_functional(scene, run_mode(scene, TraversalMode::Packet, &stats, policy, reorder),
                      "packet reordered");
    EXPECT_GT(stats.reorders, 0u);
    EXPECT_GT(stats.spill_entries, 0u) << "moved rays spill and refill from their own region";
  }
}

// Packet reordering over the given rays on one core with a fixed-latency memory.
struct ReorderRun {
  RtCoreStats stats;
  Cycle last = 0;
  std::vector<test::Retired> done;
};

ReorderRun run_reorder(const Scene& scene, std::vector<Ray> rays, PacketReorderConfig reorder) {
  TraversalUnit unit(scene.image);
  test::MockRayMemory memory(30);
  test::MockSupply supply(std::move(rays), unit, 16);
  RtCore core(0, small_config(TraversalMode::Packet, PacketPolicy::NodeFirst, reorder), unit,
              memory);
  core.set_supply(&supply.dispatcher);
  test::drive({&core});
  return {core.stats(), core.stats().last_cycle, supply.listener.done};
}

TEST(RtCoreModes, APacketIsRegroupedOnlyWhenLanesOfTheOtherKindWouldIdle) {
  Scene scene;
  std::vector<Ray> one{scene.rays[1500]};
  ReorderRun plain = run_reorder(scene, one, {});
  ReorderRun alone = run_reorder(scene, one, {1.0, 1, 7});
  EXPECT_EQ(alone.stats.reorders, 0u) << "1 of 8 lanes steps, but the others are empty";
  EXPECT_EQ(alone.last, plain.last);
}

TEST(RtCoreModes, TwoDivergingRaysAreRegroupedDownToMinWidthEachRegroupTakingItsLatency) {
  Scene scene;
  // The first pair of diffuse rays whose next visits differ in kind at some step: there a
  // packet of 8 lanes with 1 stepping and 1 idle regroups to 4, 2 and 1 lanes (both rays stay
  // in the first half until the last split), and single lanes never regroup.
  for (size_t i = 1500; i + 1 < scene.rays.size(); i += 2) {
    std::vector<Ray> pair{scene.rays[i], scene.rays[i + 1]};
    ReorderRun quick = run_reorder(scene, pair, {1.0, 1, 1});
    if (quick.stats.reorders == 0) continue;
    EXPECT_EQ(quick.stats.reorders, 3u);
    ReorderRun slow = run_reorder(scene, pair, {1.0, 1, 8});
    EXPECT_EQ(slow.last, quick.last + 3 * 7) << "three regroups, each 7 cycles longer";
    EXPECT_EQ(slow.stats.warp_steps, quick.stats.warp_steps);
    return;
  }
  FAIL() << "no pair of rays diverged";
}

TEST(RtCoreModes, ACoherentPacketIsNeverRegroupedAndDivergentOnesGainSimdEfficiency) {
  Scene scene;
  std::vector<Ray> same(16, scene.rays[1500]);
  EXPECT_EQ(run_reorder(scene, same, {0.5, 2, 3}).stats.reorders, 0u);
  std::vector<Ray> random(scene.rays.begin(), scene.rays.begin() + 400);
  RtCoreStats plain = run_reorder(scene, random, {}).stats;
  RtCoreStats reordered = run_reorder(scene, random, {0.5, 2, 3}).stats;
  double before = double(plain.active_lanes) / double(plain.packet_lanes);
  double after = double(reordered.active_lanes) / double(reordered.packet_lanes);
  EXPECT_EQ(plain.packet_lanes, plain.warp_steps * 8);
  EXPECT_GT(reordered.reorders, 0u);
  EXPECT_GT(after, before + 0.1) << "narrower packets use more of their lanes";
  EXPECT_EQ(reordered.node_steps + reordered.leaf_steps, plain.node_steps + plain.leaf_steps)
      << "the same visits, grouped differently";
}

TEST(RtCoreModes, SortedRaysReachPacketsMoreCoherentlyAndKeepTheirAnswers) {
  Scene scene;
  // Two narrow fans from the scene's centre, interleaved: +x (octant 0) and -x (octant 1).
  glm::vec3 centre = 0.5f * (scene.image.scene_lo + scene.image.scene_hi);
  scene.rays.clear();
  for (int i = 0; i < 800; ++i) {
    Ray ray;
    ray.org = centre;
    ray.dir = {i % 2 ? -1.0f : 1.0f, 0.01f * float(i % 13), 0.01f * float(i % 7)};
    scene.rays.push_back(ray);
  }
  auto run = [&](bool sorted) {
    TraversalUnit unit(scene.image);
    test::MockRayMemory memory(30);
    test::MockSupply supply(scene.rays, unit, 16 + 512);
    SortConfig sort;
    sort.key = SortKey::OctantCell;
    sort.buffer_rays = 512;
    RaySorter sorter(sort, {scene.image.scene_lo, scene.image.scene_hi}, supply.dispatcher);
    RtCore core(0, small_config(TraversalMode::Packet), unit, memory);
    core.set_supply(sorted ? static_cast<RaySupply*>(&sorter) : &supply.dispatcher);
    test::drive({&core});
    expect_functional(scene, supply.listener.done, sorted ? "sorted" : "unsorted");
    return core.stats();
  };
  RtCoreStats plain = run(false), sorted = run(true);
  auto simd = [](const RtCoreStats& s) { return double(s.active_lanes) / double(s.packet_lanes); };
  EXPECT_GT(simd(sorted), simd(plain) * 1.3) << "a warp holds one fan, not both";
  EXPECT_LT(sorted.distinct_nodes, plain.distinct_nodes);
}

TEST(RtCoreModes, PacketReorderingNeedsPacketModeAndAHalvingMinWidth) {
  RtCoreConfig c = small_config(TraversalMode::DepthFirst, PacketPolicy::NodeFirst, {0.5, 2, 1});
  EXPECT_NE(rt_core_config_problem(c), "");
  c.mode = TraversalMode::Packet;
  EXPECT_EQ(rt_core_config_problem(c), "");
  c.reorder.min_width = 3;
  EXPECT_NE(rt_core_config_problem(c), "") << "8 / 3 is no power of two";
  c.reorder.min_width = 16;
  EXPECT_NE(rt_core_config_problem(c), "") << "wider than the warp";
}

// Treelet queues whose ray buffer is `buffer`, over two cores: what moved where.
struct BufferRun {
  std::vector<test::Retired> done;
  RayBufferStats buffer;
  TreeletQueueStats queues;
  std::vector<test::MockRayMemory::Request> state_writes, state_reads;
};

BufferRun run_buffer(const Scene& scene, const RayBufferConfig& buffer) {
  TraversalUnit unit(scene.image);
  test::MockRayMemory memory0(40), memory1(60);
  test::MockSupply supply(scene.rays, unit, 64);
  TreeletQueueConfig tq;
  tq.max_rays = 64;
  tq.min_batch = 4;
  tq.buffer = buffer;
  RtCoreConfig config = small_config(TraversalMode::Treelet);
  uint32_t state_bytes = ray_state_bytes(config.stack);
  TreeletScheduler queues(tq, scene.image.treelets.count, {scene.image.node_treelet[0]},
                          supply.dispatcher, supply.pool, state_bytes);
  RtCore core0(0, config, unit, memory0), core1(1, config, unit, memory1);
  core0.set_supply(&queues);
  core1.set_supply(&queues);
  test::drive({&core0, &core1});
  BufferRun run{supply.listener.done, queues.buffer().stats(), queues.stats(), {}, {}};
  uint64_t first = ray_state_address(0, state_bytes);
  for (const auto* memory : {&memory0, &memory1}) {
    for (const auto& w : memory->writes)
      if (w.addr >= first) run.state_writes.push_back(w);
    for (const auto& r : memory->reads)
      if (r.addr >= first) run.state_reads.push_back(r);
  }
  return run;
}

TEST(RtCoreModes, RayStatesInMemoryAreWrittenOnPostponeAndReadOnResume) {
  Scene scene;
  RayBufferConfig buffer;
  buffer.place = RayBufferPlace::Memory;
  BufferRun run = run_buffer(scene, buffer);
  expect_functional(scene, run.done, "treelet, states in memory");
  uint32_t bytes = ray_state_bytes(small_config(TraversalMode::Treelet).stack);
  ASSERT_GT(run.queues.postponed, 0u);
  EXPECT_EQ(run.state_writes.size(), run.queues.postponed) << "one write per postponement";
  EXPECT_EQ(run.state_reads.size(), run.queues.postponed) << "one read per resumption";
  for (const auto& w : run.state_writes) ASSERT_EQ(w.bytes, bytes);
  for (const auto& r : run.state_reads) ASSERT_EQ(r.bytes, bytes);
  EXPECT_EQ(run.buffer.memory_bytes, 2 * run.queues.postponed * bytes);
  EXPECT_EQ(run.buffer.sram_bytes, 0u);
}

TEST(RtCoreModes, AnSramTooSmallSpillsMoreStatesTheSmallerItIs) {
  Scene scene;
  uint32_t bytes = ray_state_bytes(small_config(TraversalMode::Treelet).stack);
  uint64_t previous = 0;
  for (uint64_t states : {64u, 24u, 8u, 2u}) {
    RayBufferConfig buffer;
    buffer.bytes = states * bytes;
    buffer.overflow = RayBufferOverflow::Spill;
    BufferRun run = run_buffer(scene, buffer);
    expect_functional(scene, run.done, "treelet, spilling ray buffer");
    EXPECT_LE(run.buffer.max_in_sram, states);
    EXPECT_EQ(run.buffer.memory_writes, run.state_writes.size());
    EXPECT_EQ(run.buffer.memory_reads, run.state_reads.size());
    EXPECT_EQ(run.buffer.sram_writes + run.buffer.memory_writes, run.queues.postponed);
    if (states == 64) {
      EXPECT_EQ(run.buffer.memory_bytes, 0u) << "room for every ray: nothing spills";
    } else {
      EXPECT_GT(run.buffer.memory_bytes, previous) << states << " states of SRAM";
    }
    previous = run.buffer.memory_bytes;
  }
}

TEST(RtCoreModes, AFullSramHoldsFreshRaysBackAndLetsPostponedRaysGoOn) {
  Scene scene;
  RayBufferConfig buffer;
  buffer.bytes = 4 * ray_state_bytes(small_config(TraversalMode::Treelet).stack);
  BufferRun run = run_buffer(scene, buffer);
  expect_functional(scene, run.done, "treelet, holding ray buffer");
  EXPECT_EQ(run.buffer.max_in_sram, 4u);
  EXPECT_GT(run.buffer.held, 0u);
  EXPECT_GT(run.buffer.refused, 0u);
  EXPECT_EQ(run.buffer.memory_bytes, 0u) << "hold never spills";
  EXPECT_TRUE(run.state_writes.empty());
}

TEST(RtCoreModes, EverySpilledEntryIsReadBack) {
  Scene scene;
  for (auto& ray : scene.rays) ray.query = Query::ClosestHit;  // no stack cleared on a hit
  RtCoreStats stats;
  run_mode(scene, TraversalMode::DepthFirst, &stats);
  EXPECT_GT(stats.spill_entries, 0u) << "a 2-entry stack spills";
  EXPECT_EQ(stats.refill_entries, stats.spill_entries);
}

TEST(RtCoreModes, IdenticalRaysInAWarpAreFullyCoherent) {
  Scene scene;
  std::vector<Ray> same(16, scene.rays[1500]);  // a diffuse ray, copied
  TraversalUnit unit(scene.image);
  test::MockRayMemory memory(30);
  test::MockSupply supply(same, unit, 16);
  RtCore core(0, small_config(TraversalMode::Packet), unit, memory);
  core.set_supply(&supply.dispatcher);
  test::drive({&core});
  const RtCoreStats& s = core.stats();
  ASSERT_GT(s.warp_steps, 0u);
  EXPECT_EQ(s.active_lanes, s.warp_steps * 8) << "SIMD efficiency 1: all lanes step together";
  EXPECT_EQ(s.distinct_nodes, s.node_warp_steps) << "one node fetched per warp step";
  EXPECT_EQ(memory.reads.size(), s.warp_steps + s.refill_reads) << "fetches coalesced";
}

TEST(RtCoreModes, DivergentRaysLowerSimdEfficiency) {
  Scene scene;
  RtCoreStats stats;
  std::vector<Ray> random(scene.rays.begin(), scene.rays.begin() + 400);
  TraversalUnit unit(scene.image);
  test::MockRayMemory memory(30);
  test::MockSupply supply(random, unit, 16);
  RtCore core(0, small_config(TraversalMode::Packet), unit, memory);
  core.set_supply(&supply.dispatcher);
  test::drive({&core});
  const RtCoreStats& s = core.stats();
  double efficiency = double(s.active_lanes) / double(s.warp_steps * 8);
  EXPECT_LT(efficiency, 0.9) << "random rays diverge";
  EXPECT_GT(efficiency, 0.05);
  EXPECT_GT(double(s.distinct_nodes) / double(s.node_warp_steps), 1.5) << "lanes at other nodes";
}

}  // namespace
}  // namespace rtsim
