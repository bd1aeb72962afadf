// Instance masks and moving instances in the two-level model (issue 17): a top level per frame
// in its own address range, masked instances skipped after their record, and every ray of every
// frame and type agreeing with Embree's instances under the same settings.
#include <gtest/gtest.h>

#include <random>

#include "model/bvh/two_level.h"
#include "model/units/traversal.h"
#include "model/verify/verifier.h"
#include "model_test_util.h"
#include "tests/instanced_world.h"
#include "traces/embree_scene.h"

namespace rtsim {
namespace {

// Instance 1 is seen only by rays whose mask has bit 0, instance 4 only by bit 1; shadow rays
// (mask 2) miss instance 1, AO rays (mask 1) miss instance 4. Instances 0 and 5 move over three
// frames: slid, turned and grown.
InstanceSettings masks_and_motion() {
  InstanceSettings s;
  s.masks = {{1, 0x01}, {4, 0x02}};
  s.ray_masks[size_t(RayType::Shadow)] = 0x02;
  s.ray_masks[size_t(RayType::AO)] = 0x01;
  Motion m;
  m.axis = glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f));
  m.keys = {{}, {{3.0f, 0.0f, -2.0f}, 120.0f, 1.5f}, {{-4.0f, 2.0f, 1.0f}, 200.0f, 0.5f}};
  s.motions = {m};
  s.moving = {{0, 0}, {5, 0}};
  s.frames = 3;
  return s;
}

Ray typed_world_ray(std::mt19937& rng, int i) {
  Ray ray = test::world_ray(rng);
  ray.type = RayType(i % kRayTypeCount);
  ray.frame = uint32_t(i / kRayTypeCount) % 3;
  ray.query = i % 5 == 0 ? Query::AnyHit : Query::ClosestHit;
  return ray;
}

TEST(InstanceMotion, EachFrameHasItsOwnTopLevelBeforeTheSharedBottomLevels) {
  InstancedMesh g = test::instanced_world();
  InstanceSettings settings = masks_and_motion();
  apply_masks(g, settings);
  TwoLevelBvh bvh = build_two_level_bvh(g, BvhConfig{}, {}, settings);
  ASSERT_EQ(bvh.frame_tops.size(), 2u);
  ASSERT_EQ(bvh.top_builds.size(), 3u);
  BvhView view(bvh);
  std::vector<const BvhImage*> levels = view.levels();
  ASSERT_EQ(levels.size(), 3 + g.meshes.size());
  uint64_t end = 0;
  uint32_t treelets = 0;
  for (const BvhImage* level : levels) {  // disjoint, in order, treelets numbered across
    EXPECT_GE(level->node_base, end);
    end = level->triangle_base + level->triangles.size();
    EXPECT_EQ(level->treelet_base, treelets);
    treelets = level->treelet_base + std::max<uint32_t>(level->treelets.count, 1);
  }
  EXPECT_EQ(view.top_end_address(),
            bvh.frame_tops.back().triangle_base + bvh.frame_tops.back().triangles.size());
  EXPECT_EQ(&view.top_of(0), &bvh.top);
  EXPECT_EQ(&view.top_of(2), &bvh.frame_tops[1]);
  EXPECT_EQ(&view.top_of(9), &bvh.frame_tops[1]) << "later frames: the last pose";
  EXPECT_EQ(view.root_treelets().size(), 3u);
  for (uint32_t f = 0; f < 3; ++f) {
    EXPECT_EQ(bvh.top_builds[f].nodes, view.top_of(f).node_count);
    for (uint32_t p = 0; p < view.top_of(f).triangle_count; ++p) {
      InstanceRecord r = read_instance_record(view.top_of(f), p);
      EXPECT_EQ(r.mask, g.instances[r.instance].mask) << "frame " << f;
    }
  }
}

TEST(InstanceMotion, EveryFrameAndRayTypeAgreesWithEmbree) {
  InstancedMesh g = test::instanced_world();
  InstanceSettings settings = masks_and_motion();
  apply_masks(g, settings);
  EmbreeScene unmasked_still(test::instanced_world(), 1);
  for (const BvhConfig& config : test::all_configs()) {
    SCOPED_TRACE(describe(config));
    TwoLevelBvh bvh = build_two_level_bvh(g, config, {}, settings);
    TraversalUnit unit(bvh);
    VerifierSetup checks = make_verifier(unit, {}, g, settings);
    std::mt19937 rng(41);
    int changed = 0;
    for (int i = 0; i < 4000; ++i) {
      Ray ray = typed_world_ray(rng, i);
      checks.verifier->check(ray);
      Hit still = unmasked_still.trace(ray), moved = checks.reference->trace(ray);
      changed += still.hit() != moved.hit() || still.instance != moved.instance;
    }
    const VerifyReport& r = checks.verifier->report();
    EXPECT_EQ(r.unexplained(), 0u);
    EXPECT_GE(r.agree, r.rays - r.rays / 500);
    EXPECT_GT(r.model_hits, 800u);
    EXPECT_GT(changed, 200) << "masks and motion must change what the rays hit";
  }
}

TEST(InstanceMotion, AMaskedInstanceIsReadButNotEntered) {
  InstancedMesh g = test::instanced_world();
  InstanceSettings settings = masks_and_motion();
  apply_masks(g, settings);
  TwoLevelBvh bvh = build_two_level_bvh(g, BvhConfig{}, {}, settings);
  TraversalUnit unit(bvh);
  TraversalState s;
  // Straight down at instance 1 (the box scaled to 2 x 0.5 x 3 at x = 6) from +z.
  Ray ray = test::ray_to({6.1f, 0.1f, 9.0f}, {6.1f, 0.1f, 0.0f});
  Hit camera = unit.trace(s, ray);
  ASSERT_TRUE(camera.hit());
  EXPECT_EQ(camera.instance, 1u);
  EXPECT_EQ(s.counters.trav_instances, 1u);
  ray.type = RayType::Shadow;
  Hit shadow = unit.trace(s, ray);
  EXPECT_FALSE(shadow.hit());
  EXPECT_EQ(s.counters.trav_instances, 0u) << "no transform, no BLAS";
  size_t records = 0;
  for (const MemoryAccess& a : s.accesses) records += a.kind == AccessKind::Instance;
  EXPECT_EQ(records, 1u) << "the record is read to find its mask";
}

}  // namespace
}  // namespace rtsim
