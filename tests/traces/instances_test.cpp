// Instanced geometry (issue 17): the checks on it, flattening, and Embree's two-level reference
// against Embree on the flattened copy, with translated, scaled, rotated, sheared and mirrored
// instances.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "traces/embree_scene.h"
#include "traces/instances.h"
#include "tests/instanced_world.h"

namespace rtsim {
namespace {

TEST(Instances, ChecksNameWhatIsWrong) {
  InstancedMesh g = test::instanced_world();
  EXPECT_EQ(instancing_problem(g), "");
  auto problem = [&](auto edit) {
    InstancedMesh bad = test::instanced_world();
    edit(bad);
    return instancing_problem(bad);
  };
  EXPECT_EQ(problem([](InstancedMesh& b) { b.instances[2].mesh = 7; }),
            "instance 2 names mesh 7 of 2");
  EXPECT_EQ(problem([](InstancedMesh& b) { b.instances[1].to_world.linear[2] = glm::vec3(0); }),
            "instance 1 has a transform that is not invertible");
  EXPECT_EQ(problem([](InstancedMesh& b) { b.instances[3].to_world.offset.y = NAN; }),
            "instance 3 has a transform that is not finite");
  EXPECT_EQ(problem([](InstancedMesh& b) { b.meshes[1].triangles.clear(); }),
            "mesh 1 has no triangles");
  EXPECT_EQ(problem([](InstancedMesh& b) { b.instances.clear(); }), "no instances");
}

TEST(Instances, FlattenPlacesEveryInstanceInWorldSpace) {
  InstancedMesh g = test::instanced_world();
  EXPECT_EQ(g.unique_triangles(), 12u + 8u);
  EXPECT_EQ(g.instanced_triangles(), 5u * 12u + 2u * 8u);
  FlatMesh flat = flatten(g);
  ASSERT_EQ(flat.mesh.triangle_count(), g.instanced_triangles());
  ASSERT_EQ(flat.flat_offsets.size(), g.instances.size());
  EXPECT_EQ(flat.flat_offsets[1], 12u);
  EXPECT_EQ(flat.flat_offsets[5], 4u * 12u + 8u);
  const Instance& scaled = g.instances[1];
  glm::vec3 corner = flat.mesh.vertex(flat.flat_offsets[1] + 0, 0);
  EXPECT_EQ(corner, scaled.to_world.point(g.meshes[0].vertex(0, 0)));
  Transform back = inverse(scaled.to_world);
  glm::vec3 round_trip = back.point(scaled.to_world.point({0.3f, -0.2f, 0.9f}));
  EXPECT_NEAR(round_trip.x, 0.3f, 1e-6f);
  EXPECT_NEAR(round_trip.z, 0.9f, 1e-6f);
}

// Rays from a shell around the world towards random points inside it: the instanced scene and
// the flattened one find the same triangle at the same t (a ray that lands on an edge shared by
// two triangles of one mesh may name either, at the same t).
TEST(Instances, EmbreeInstancesAgreeWithTheFlattenedScene) {
  InstancedMesh g = test::instanced_world();
  FlatMesh flat = flatten(g);
  EmbreeScene instanced(g, 1), flattened(flat.mesh, 1);
  std::mt19937 rng(17);
  int hits = 0, other_triangle = 0, occluded_checked = 0;
  for (int i = 0; i < 20000; ++i) {
    Ray ray = test::world_ray(rng);
    Hit a = instanced.intersect(ray), b = flattened.intersect(ray);
    ASSERT_EQ(a.hit(), b.hit()) << "ray " << i;
    if (!a.hit()) {
      EXPECT_EQ(a.instance, kNoHit);
      continue;
    }
    ++hits;
    ASSERT_LT(a.instance, g.instances.size());
    EXPECT_NEAR(a.t, b.t, 1e-4f * b.t) << "ray " << i;
    uint64_t flat_prim = flat.flat_offsets[a.instance] + a.prim;
    other_triangle += flat_prim != b.prim;
    EXPECT_EQ(b.instance, kNoHit) << "a single-level scene names no instance";
    ray.tmax = b.t * 0.999f;
    ray.query = Query::AnyHit;
    EXPECT_EQ(instanced.occluded(ray), flattened.occluded(ray)) << "ray " << i;
    ++occluded_checked;
  }
  EXPECT_GT(hits, 5000) << "the rays must mostly hit for the check to mean something";
  EXPECT_LE(other_triangle, hits / 500) << "only shared edges may name the other triangle";
  EXPECT_EQ(occluded_checked, hits);
}

}  // namespace
}  // namespace rtsim
