// One RT unit alone with mock neighbours: the exact cycle of every stage of a ray (setup,
// fetch, memory, box and triangle units, control), issue width, and no progress while the
// memory never answers.
#include <gtest/gtest.h>

#include "model/sched/rt_core.h"
#include "tests/model/model_test_util.h"
#include "tests/sched/drive_cores.h"
#include "tests/sched/mock_neighbours.h"

namespace rtsim {
namespace {

// One triangle in front of a ray: a root node step, a leaf step, then done.
struct OneTriangle {
  OneTriangle() {
    test::add_triangle(mesh, {-1, -1, 5}, {1, -1, 5}, {0, 1, 5});
    image = build_bvh_image(mesh, BvhConfig{});
    ray.dir = {0, 0, 1};
  }
  TriangleMesh mesh;
  BvhImage image;
  Ray ray;
};

RtCoreConfig timing_config() {
  RtCoreConfig c;
  c.warps = 1;
  c.warp_size = 1;
  c.setup_latency = 4;
  c.control_latency = 1;
  c.box = {1, 8, 8};
  c.triangle = {1, 1, 12};
  return c;
}

TEST(RtCoreTiming, EveryStageTakesExactlyItsLatency) {
  OneTriangle scene;
  TraversalUnit unit(scene.image);
  test::MockRayMemory memory(50);
  test::MockSupply supply({scene.ray}, unit, 1, {1.0, 10});
  RtCore core(0, timing_config(), unit, memory);
  core.set_supply(&supply.dispatcher);
  test::drive({&core});
  ASSERT_EQ(supply.listener.done.size(), 1u);
  const test::Retired& r = supply.listener.done[0];
  ASSERT_EQ(r.counters.trav_nodes, 1u);
  ASSERT_EQ(r.counters.trav_leaves, 1u);
  ASSERT_TRUE(r.hit.hit());
  // Arrival 0 + dispatch latency 10, setup 4: the node fetch at 14.
  ASSERT_EQ(memory.reads.size(), 2u);
  EXPECT_EQ(memory.reads[0].at, 14u) << "node fetch after dispatch and setup";
  EXPECT_EQ(memory.reads[0].bytes, scene.image.node_size);
  // Data at 64, box unit 8, control 1: the leaf fetch at 73.
  EXPECT_NE(memory.reads[1].at, 72u) << "not one cycle early";
  EXPECT_EQ(memory.reads[1].at, 73u) << "leaf fetch after memory, box unit and control";
  // Data at 123, triangle unit 12, control 1: the done step retires the ray at 136.
  EXPECT_EQ(r.cycle, 136u);
  EXPECT_EQ(core.stats().node_steps, 1u);
  EXPECT_EQ(core.stats().leaf_steps, 1u);
  EXPECT_EQ(core.box().stats().tests, 1u) << "the root has one child box";
  EXPECT_EQ(core.stats().issues, 3u) << "the node step, the leaf step and the step that retires";
}

// Two levels: the triangle as one instance, moved along z. The TLAS root, the instance step
// (its record, then the transform unit), the BLAS root and the leaf.
TEST(RtCoreTiming, AnInstanceStepTakesItsRecordFetchAndTheTransformLatency) {
  OneTriangle scene;
  InstancedMesh world;
  world.meshes = {scene.mesh};
  Transform moved;
  moved.offset = {0, 0, 2};
  world.instances = {{0, moved}};
  TwoLevelBvh bvh = build_two_level_bvh(world, BvhConfig{});
  TraversalUnit unit(bvh);
  test::MockRayMemory memory(50);
  test::MockSupply supply({scene.ray}, unit, 1, {1.0, 10});
  RtCoreConfig c = timing_config();
  c.transform = {1, 1, 5};
  RtCore core(0, c, unit, memory);
  core.set_supply(&supply.dispatcher);
  test::drive({&core});
  ASSERT_EQ(supply.listener.done.size(), 1u);
  const test::Retired& r = supply.listener.done[0];
  ASSERT_TRUE(r.hit.hit());
  EXPECT_FLOAT_EQ(r.hit.t, 7.0f);
  ASSERT_EQ(memory.reads.size(), 4u);
  EXPECT_EQ(memory.reads[0].at, 14u) << "TLAS root after dispatch and setup";
  EXPECT_EQ(memory.reads[1].at, 73u) << "instance record after memory, box unit and control";
  EXPECT_EQ(memory.reads[1].bytes, kInstanceRecordBytes);
  EXPECT_EQ(memory.reads[1].addr, bvh.top.triangle_base);
  // Data at 123, transform 5, control 1.
  EXPECT_EQ(memory.reads[2].at, 129u) << "BLAS root after memory, transform unit and control";
  EXPECT_EQ(memory.reads[2].addr, bvh.bottom[0].node_base);
  EXPECT_EQ(memory.reads[3].at, 188u) << "leaf after memory, box unit and control";
  // Data at 238, triangle unit 12, control 1; the step that retires pops the way back too.
  EXPECT_EQ(r.cycle, 251u);
  EXPECT_EQ(core.stats().node_steps, 2u);
  EXPECT_EQ(core.stats().top_node_steps, 1u);
  EXPECT_EQ(core.stats().instance_steps, 1u);
  EXPECT_EQ(core.transform().stats().tests, 1u);
}

// The triangle alpha-tested with a 2x2 mask: texel 3 (u, v >= 0.5) decides for a ray through
// the triangle's middle; its alpha is `alpha`.
BvhImage alpha_image(OneTriangle& scene, uint8_t alpha) {
  auto mask = std::make_shared<AlphaMask>();
  mask->width = mask->height = 2;
  mask->alpha = {255, 255, 255, alpha};
  mask->texture_offset = 8192;
  auto a = std::make_shared<TriangleAlpha>();
  a->masks = {mask};
  a->mask_of = {0};
  a->uv = {{glm::vec2(0.5f, 0.5f), glm::vec2(0.9f, 0.9f), glm::vec2(0.6f, 0.9f)}};
  scene.mesh.alpha = a;
  return build_bvh_image(scene.mesh, BvhConfig{});
}

TEST(RtCoreTiming, OneAnyHitCallCostsExactlyItsLatencyAndReadsItsTexel) {
  for (uint8_t alpha : {uint8_t(255), uint8_t(0)}) {
    OneTriangle scene;
    BvhImage image = alpha_image(scene, alpha);
    TraversalUnit unit(image);
    test::MockRayMemory memory(50);
    test::MockSupply supply({scene.ray}, unit, 1, {1.0, 10});
    RtCoreConfig c = timing_config();
    c.anyhit.shader = {1, 1, 37};
    RtCore core(0, c, unit, memory);
    core.set_supply(&supply.dispatcher);
    test::drive({&core});
    ASSERT_EQ(supply.listener.done.size(), 1u);
    const test::Retired& r = supply.listener.done[0];
    EXPECT_EQ(r.hit.hit(), alpha == 255) << "a hole lets the ray through";
    // The texel read goes out with the leaf's; the call follows the triangle test.
    ASSERT_EQ(memory.reads.size(), 3u);
    EXPECT_EQ(memory.reads[2].at, 73u);
    EXPECT_EQ(memory.reads[2].addr, kTextureBase + 8192 + 3 * kTexelBytes);
    EXPECT_EQ(memory.reads[2].bytes, c.anyhit.read_bytes);
    EXPECT_EQ(r.cycle, 136u + 37u) << "the opaque triangle's 136 cycles and one round trip";
    EXPECT_EQ(core.stats().anyhit_calls, 1u);
    EXPECT_EQ(core.stats().anyhit_cycles, 37u);
    EXPECT_EQ(core.anyhit_shader().stats().requests, 1u);
  }
}

TEST(RtCoreTiming, DataReportedLaterStepsExactlyAsDataKnownAtOnce) {
  OneTriangle scene;
  TraversalUnit unit(scene.image);
  std::vector<Ray> rays(6, scene.ray);
  for (TraversalMode mode : {TraversalMode::DepthFirst, TraversalMode::Packet}) {
    RtCoreConfig c = timing_config();
    c.mode = mode;
    c.warp_size = 3;
    c.warps = 2;
    std::vector<Cycle> retired[2];
    for (bool deferred : {false, true}) {
      test::MockRayMemory memory(50, deferred);
      test::MockSupply supply(rays, unit, 6);
      RtCore core(0, c, unit, memory);
      core.set_supply(&supply.dispatcher);
      test::drive({&core}, [&] { memory.answer_all(); });
      for (const test::Retired& r : supply.listener.done) retired[deferred].push_back(r.cycle);
      EXPECT_EQ(core.stats().waited_reads, deferred ? memory.reads.size() : 0u);
      EXPECT_EQ(core.stats().late_data, 0u);
      EXPECT_EQ(core.waiting_reads(), 0u);
    }
    ASSERT_EQ(retired[0].size(), 6u) << traversal_mode_name(mode);
    EXPECT_EQ(retired[0], retired[1]) << traversal_mode_name(mode);
  }
}

TEST(RtCoreTiming, IssueWidthDefersTheFourthRay) {
  OneTriangle scene;
  TraversalUnit unit(scene.image);
  test::MockRayMemory memory(50);
  std::vector<Ray> rays(4, scene.ray);
  test::MockSupply supply(rays, unit, 4);  // all four arrive at cycle 0
  RtCoreConfig c = timing_config();
  c.warp_size = 4;
  c.issue_per_cycle = 3;
  RtCore core(0, c, unit, memory);
  core.set_supply(&supply.dispatcher);
  test::drive({&core});
  ASSERT_GE(memory.reads.size(), 4u);
  EXPECT_EQ(memory.reads[0].at, 4u);
  EXPECT_EQ(memory.reads[2].at, 4u) << "three steps start in one cycle";
  EXPECT_EQ(memory.reads[3].at, 5u) << "the fourth starts a cycle later";
  EXPECT_EQ(core.stats().issue_stalls, 1u);
}

// A warp of two: a hit (root and leaf steps) and a miss (the root only), then a third ray.
// Refilled by warp, the third ray comes once both have retired; by slot, once the miss has.
TEST(RtCoreTiming, SlotRefillTakesARayWhenItsSlotFreesAndWarpRefillWhenTheWarpDoes) {
  OneTriangle scene;
  TraversalUnit unit(scene.image);
  Ray miss = scene.ray;
  miss.dir = {0, 0, -1};
  std::vector<Ray> rays{scene.ray, miss, scene.ray};
  for (Refill refill : {Refill::Warp, Refill::Slot}) {
    test::MockRayMemory memory(50);
    test::MockSupply supply(rays, unit, 3, {1.0, 10});
    RtCoreConfig c = timing_config();
    c.warp_size = 2;
    c.refill = refill;
    RtCore core(0, c, unit, memory);
    core.set_supply(&supply.dispatcher);
    test::drive({&core});
    ASSERT_EQ(supply.listener.done.size(), 3u);
    Cycle retired[3];
    for (const test::Retired& r : supply.listener.done) retired[r.sequence] = r.cycle;
    ASSERT_LT(retired[1], retired[0]) << "the miss finishes first";
    // The third ray's root fetch: delivered when a slot frees, dispatch latency 10, setup 4.
    ASSERT_EQ(memory.reads.size(), 5u) << "root, root, leaf; then root and leaf";
    Cycle freed = refill == Refill::Slot ? retired[1] : retired[0];
    EXPECT_EQ(memory.reads[3].at, freed + 14) << refill_name(refill);
    EXPECT_EQ(memory.reads[3].addr, memory.reads[0].addr);
  }
}

TEST(RtCoreTiming, PacketModeCannotRefillSlots) {
  RtCoreConfig c = timing_config();
  c.mode = TraversalMode::Packet;
  c.refill = Refill::Slot;
  EXPECT_NE(rt_core_config_problem(c).find("packet mode"), std::string::npos);
  c.mode = TraversalMode::DepthFirst;
  EXPECT_EQ(rt_core_config_problem(c), "");
}

TEST(RtCoreTiming, NoProgressWhileMemoryNeverAnswers) {
  OneTriangle scene;
  TraversalUnit unit(scene.image);
  test::MockRayMemory memory(Cycle(1) << 40);
  test::MockSupply supply({scene.ray}, unit, 1);
  RtCore core(0, timing_config(), unit, memory);
  core.set_supply(&supply.dispatcher);
  EXPECT_EQ(core.poll(0), 1u) << "the ray was taken";
  EXPECT_EQ(core.advance(1000), 1u) << "its first step issued a fetch";
  EXPECT_EQ(core.advance(1000000), 0u) << "then nothing: the data never comes";
  EXPECT_FALSE(core.finished());
  EXPECT_NE(core.dump().find("1 of 1 ray slots busy"), std::string::npos) << core.dump();
}

}  // namespace
}  // namespace rtsim
