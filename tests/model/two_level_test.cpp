// Two-level BVH (issue 17): the top level over instances and a bottom level per unique mesh, in
// one address space; the traversal unit walks it with instance transforms and finds what
// Embree's instances find, and what the flattened scene finds, for every node format.
#include <gtest/gtest.h>

#include <random>

#include "model/bvh/two_level.h"
#include "model/units/traversal.h"
#include "model/verify/verifier.h"
#include "model_test_util.h"
#include "tests/instanced_world.h"
#include "traces/embree_scene.h"
#include "traces/error.h"

namespace rtsim {
namespace {

TEST(TwoLevel, HoldsUniqueGeometryOnceInDisjointRegions) {
  InstancedMesh g = test::instanced_world();
  TwoLevelBvh bvh = build_two_level_bvh(g, BvhConfig{});
  ASSERT_EQ(bvh.bottom.size(), g.meshes.size());
  EXPECT_EQ(bvh.top.triangle_count, g.instances.size()) << "one instance record each";
  EXPECT_EQ(bvh.top.triangle_stride, kInstanceRecordBytes);
  uint64_t triangles = 0;
  for (const BvhImage& b : bvh.bottom) triangles += b.triangle_count;
  EXPECT_EQ(triangles, g.unique_triangles());
  // Regions in address order: TLAS nodes, instance records, then each BLAS's nodes, triangles.
  uint64_t end = bvh.top.node_base;
  std::vector<const BvhImage*> images{&bvh.top};
  for (const BvhImage& b : bvh.bottom) images.push_back(&b);
  for (const BvhImage* image : images) {
    EXPECT_GE(image->node_base, end);
    EXPECT_GE(image->triangle_base, image->node_base + image->nodes.size());
    end = image->triangle_base + image->triangles.size();
  }
  // Every record names its instance and mesh, with the inverse of the instance's transform.
  std::vector<bool> seen(g.instances.size(), false);
  for (uint32_t p = 0; p < bvh.top.triangle_count; ++p) {
    InstanceRecord r = read_instance_record(bvh.top, p);
    ASSERT_LT(r.instance, g.instances.size());
    seen[r.instance] = true;
    EXPECT_EQ(r.blas, g.instances[r.instance].mesh);
    glm::vec3 back = r.to_object.point(g.instances[r.instance].to_world.point({0.5f, -0.25f, 1}));
    EXPECT_NEAR(back.x, 0.5f, 1e-4f);
    EXPECT_NEAR(back.y, -0.25f, 1e-4f);
    EXPECT_NEAR(back.z, 1.0f, 1e-4f);
  }
  EXPECT_EQ(std::count(seen.begin(), seen.end(), true), long(g.instances.size()));
}

TEST(TwoLevel, RejectsBadInstancesNamingThem) {
  InstancedMesh g = test::instanced_world();
  g.instances[4].mesh = 9;
  try {
    build_two_level_bvh(g, BvhConfig{});
    FAIL() << "accepted an instance of a mesh that does not exist";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("instance 4 names mesh 9 of 2"), std::string::npos)
        << e.what();
  }
}

// Rays from a shell around the world towards random points inside it, for every node format.
TEST(TwoLevel, TraversalFindsWhatEmbreeInstancesAndTheFlatSceneFind) {
  InstancedMesh g = test::instanced_world();
  FlatMesh flat = flatten(g);
  EmbreeScene embree(g, 1);
  for (const BvhConfig& config : test::all_configs()) {
    SCOPED_TRACE(describe(config));
    TwoLevelBvh bvh = build_two_level_bvh(g, config);
    BvhImage flat_image = build_bvh_image(flat.mesh, config);
    TraversalUnit unit(bvh), flat_unit(flat_image);
    TraversalState s, flat_s;
    std::mt19937 rng(29);
    int hits = 0, other_triangle = 0, transforms = 0;
    for (int i = 0; i < 4000; ++i) {
      Ray ray = test::world_ray(rng);
      Hit ours = unit.trace(s, ray), reference = embree.intersect(ray);
      Hit flat_hit = flat_unit.trace(flat_s, ray);
      transforms += int(s.counters.trav_instances);
      ASSERT_EQ(ours.hit(), reference.hit()) << "ray " << i;
      ASSERT_EQ(ours.hit(), flat_hit.hit()) << "ray " << i;
      if (!ours.hit()) continue;
      ++hits;
      EXPECT_NEAR(ours.t, reference.t, 1e-4f * reference.t) << "ray " << i;
      EXPECT_NEAR(ours.t, flat_hit.t, 1e-4f * flat_hit.t) << "ray " << i;
      other_triangle += ours.instance != reference.instance || ours.prim != reference.prim;
      EXPECT_EQ(flat.flat_offsets[ours.instance] + ours.prim, flat_hit.prim) << "ray " << i;
      // Occlusion just short of the hit, and up to it.
      ray.query = Query::AnyHit;
      ray.tmax = ours.t * 0.999f;
      EXPECT_EQ(unit.trace(s, ray).hit(), embree.occluded(ray)) << "ray " << i;
      ray.tmax = ours.t * 1.001f;
      EXPECT_TRUE(unit.trace(s, ray).hit()) << "ray " << i;
    }
    EXPECT_GT(hits, 1000);
    EXPECT_LE(other_triangle, hits / 500) << "only shared edges may name the other triangle";
    EXPECT_GT(transforms, hits) << "rays enter instances they miss, too";
  }
}

// Flat ids without a flattened copy: the corners are flatten()'s, bit for bit, and a hit that
// names an instance becomes the flattened mesh's triangle.
TEST(TwoLevel, FlatTrianglesOfInstancesAreTheFlattenedMesh) {
  InstancedMesh g = test::instanced_world();
  FlatMesh flat = flatten(g);
  FlatTriangles triangles(g);
  ASSERT_EQ(triangles.count(), flat.mesh.triangle_count());
  for (uint64_t t = 0; t < triangles.count(); ++t) {
    std::array<glm::vec3, 3> c = triangles.corners(t);
    for (int k = 0; k < 3; ++k) ASSERT_EQ(c[k], flat.mesh.vertex(t, k)) << "triangle " << t;
    FlatTriangles::Place at = triangles.locate(t);
    ASSERT_EQ(flat.flat_offsets[at.instance] + at.prim, t);
  }
  Hit hit;
  hit.instance = 3;
  hit.prim = 2;
  EXPECT_EQ(triangles.flat(hit).prim, flat.flat_offsets[3] + 2);
  hit.prim = kAnyPrim;
  EXPECT_EQ(triangles.flat(hit).prim, kAnyPrim) << "an any-hit answer names no triangle";
  EXPECT_NE(instanced_fingerprint(g), mesh_fingerprint(flat.mesh));
  g.instances[1].to_world.offset.x += 1.0f;
  EXPECT_NE(instanced_fingerprint(g), instanced_fingerprint(test::instanced_world()));
}

// The verifier of `rtsim verify --instances`: hits named by instance and triangle, judged as
// flat ids with no flattened copy; transformed instances leave nothing unexplained.
TEST(TwoLevel, VerifierJudgesInstancedHitsAsFlatIds) {
  InstancedMesh g = test::instanced_world();
  EmbreeScene instanced(g, 1);
  TwoLevelBvh bvh = build_two_level_bvh(g, BvhConfig{});
  TraversalUnit unit(bvh);
  Verifier verifier(FlatTriangles(g), unit, instanced);
  std::mt19937 rng(5);
  for (int i = 0; i < 3000; ++i) {
    Ray ray = test::world_ray(rng);
    ray.query = i % 3 == 0 ? Query::AnyHit : Query::ClosestHit;
    verifier.check(ray);
  }
  const VerifyReport& r = verifier.report();
  EXPECT_EQ(r.unexplained(), 0u);
  EXPECT_GE(r.agree, r.rays - r.rays / 500);
  EXPECT_GT(r.model_hits, 500u) << "the rays must mostly hit for the check to mean something";
  EXPECT_GT(r.counters.trav_instances, r.model_hits);
}

TEST(TwoLevel, ARayThatMissesEveryInstanceBoxTransformsNothing) {
  InstancedMesh g = test::instanced_world();
  TwoLevelBvh bvh = build_two_level_bvh(g, BvhConfig{});
  TraversalUnit unit(bvh);
  TraversalState s;
  Hit hit = unit.trace(s, test::ray_to({100, 100, 100}, {200, 100, 100}));
  EXPECT_FALSE(hit.hit());
  EXPECT_EQ(s.counters.trav_instances, 0u);
  EXPECT_EQ(hit.instance, kNoHit);
  // Straight at the untransformed box (instance 0), from +z: its top face, at t = 4.
  hit = unit.trace(s, test::ray_to({0.1f, 0.2f, 5.0f}, {0.1f, 0.2f, 0.0f}));
  ASSERT_TRUE(hit.hit());
  EXPECT_EQ(hit.instance, 0u);
  EXPECT_FLOAT_EQ(hit.t, 0.8f) << "ray_to's direction runs to the target at t = 1";
  EXPECT_GE(s.counters.trav_instances, 1u);
  size_t instance_fetches = 0;
  for (const MemoryAccess& a : s.accesses) instance_fetches += a.kind == AccessKind::Instance;
  EXPECT_EQ(instance_fetches, s.counters.trav_instances);
  // A denormal-scale direction (rescaled by a power of two in each level's ray setup): the
  // same hit at t scaled back.
  Ray tiny = test::ray_to({0.1f, 0.2f, 5.0f}, {0.1f, 0.2f, 0.0f});
  tiny.dir *= 0x1p-100f;
  hit = unit.trace(s, tiny);
  ASSERT_TRUE(hit.hit());
  EXPECT_EQ(hit.instance, 0u);
  EXPECT_FLOAT_EQ(hit.t, 0.8f * 0x1p100f);
}

// An instance scaled by 2^-40: its object-space direction is beyond 2^32, so the BLAS's ray
// setup rescales it and t must come back through the exponent; an any-hit query that ends in
// it ends in world space; without an access list an instance step names no fetch.
TEST(TwoLevel, AnInstanceScaledBy2ToTheMinus40) {
  InstancedMesh g;
  g.meshes = {test::box_mesh()};
  g.instances = {{0, test::make(glm::mat3(0x1p-40f), {0.0f, 0.0f, 0.0f})},
                 {0, test::make(glm::mat3(1.0f), {0.0f, 0.0f, -10.0f})}};
  TwoLevelBvh bvh = build_two_level_bvh(g, BvhConfig{});
  TraversalUnit unit(bvh);
  TraversalState s;
  Ray ray = test::ray_to({0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f});
  Hit hit = unit.trace(s, ray);
  ASSERT_TRUE(hit.hit());
  EXPECT_EQ(hit.instance, 0u) << "the tiny box, in front of the big one";
  EXPECT_FLOAT_EQ(hit.t, 1.0f - 0x1p-40f);
  EXPECT_EQ(s.level, &bvh.top);
  ray.query = Query::AnyHit;
  hit = unit.trace(s, ray);
  EXPECT_EQ(hit.prim, kAnyPrim);
  EXPECT_EQ(s.level, &bvh.top) << "an any-hit query ends in world space";
  EXPECT_EQ(s.instance, kNoHit);
  EXPECT_EQ(s.ray.t_exponent, 0);
  // Past the tiny box (its z range is +-2^-40), the big one answers, at world t.
  ray = test::ray_to({5.0f, 0.0f, 1.0f}, {5.0f, 0.0f, -20.0f});
  ray.dir = glm::vec3(-5.0f, 0.0f, -11.0f);
  hit = unit.trace(s, ray);
  ASSERT_TRUE(hit.hit());
  EXPECT_EQ(hit.instance, 1u);
  TraversalConfig quiet;
  quiet.record_accesses = false;
  TraversalUnit unrecorded(bvh, quiet);
  unrecorded.begin(s, test::ray_to({0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f}));
  for (StepResult r = unrecorded.step(s); r.kind != StepKind::Done; r = unrecorded.step(s))
    EXPECT_EQ(r.access_count, 0u) << "no access list, no fetch named in it";
}

}  // namespace
}  // namespace rtsim
