// The double-precision arbiter: exact recomputation and the classification of disagreements.
#include "model/verify/arbiter.h"

#include <gtest/gtest.h>

#include "model_test_util.h"

namespace rtsim {
namespace {

// Quad split along its diagonal (triangles 0, 1), a duplicate of triangle 0 (2), a degenerate
// triangle (3) and a triangle seen edge-on from the test rays (4).
TriangleMesh scene() {
  TriangleMesh mesh;
  test::add_triangle(mesh, {0, 0, 0}, {1, 0, 0}, {1, 1, 0});
  test::add_triangle(mesh, {0, 0, 0}, {1, 1, 0}, {0, 1, 0});
  test::add_triangle(mesh, {0, 0, 0}, {1, 0, 0}, {1, 1, 0});
  test::add_triangle(mesh, {5, 0, 0}, {6, 0, 0}, {7, 0, 0});
  test::add_triangle(mesh, {10, 0, -1}, {10, 1, -1}, {10, 0, 1});
  return mesh;
}

TEST(Arbiter, ExactIntersectionInDouble) {
  TriangleMesh mesh = scene();
  Ray ray = test::ray_to({0.75f, 0.25f, 2.0f}, {0.75f, 0.25f, 0.0f});
  ExactHit ex = exact_intersect(mesh, 0, ray);
  EXPECT_TRUE(ex.hit());
  EXPECT_DOUBLE_EQ(ex.t, 1.0);
  EXPECT_NEAR(ex.min_barycentric, 0.25, 1e-12);
  EXPECT_NEAR(ex.cosine, 1.0, 1e-12);
  EXPECT_FALSE(exact_intersect(mesh, 1, ray).hit());
}

TEST(Arbiter, AgreementIsNotAMismatch) {
  TriangleMesh mesh = scene();
  EmbreeScene embree(mesh, 1);
  Arbiter arbiter(mesh, embree);
  Ray ray = test::ray_to({0.75f, 0.25f, 2.0f}, {0.75f, 0.25f, 0.0f});
  EXPECT_TRUE(arbiter.judge(ray, test::hit_of(0, 2.0f), 0, 2.0f).agree);
  EXPECT_TRUE(arbiter.judge(ray, Hit{}, kNoHit, 0.0f).agree);
  EXPECT_TRUE(arbiter.judge(ray, test::hit_of(0, 2.0f), 0, 2.0f + 1e-6f).agree)
      << "within tolerance";
}

TEST(Arbiter, SharedEdgeHitsAreExplained) {
  TriangleMesh mesh = scene();
  EmbreeScene embree(mesh, 1);
  Arbiter arbiter(mesh, embree);
  Ray ray = test::ray_to({0.5f, 0.5f, 3.0f}, {0.5f, 0.5f, 0.0f});
  Verdict v = arbiter.judge(ray, test::hit_of(0, 3.0f), 1, 3.0f);
  EXPECT_FALSE(v.agree);
  EXPECT_EQ(v.cls, MismatchClass::EdgeOrVertex);
  EXPECT_EQ(v.right, RightSide::Both);
  // One side missing the edge entirely: the side that hit is right.
  Verdict slipped = arbiter.judge(ray, Hit{}, 1, 3.0f);
  EXPECT_EQ(slipped.cls, MismatchClass::EdgeOrVertex);
  EXPECT_EQ(slipped.right, RightSide::Both) << "exactly on the edge: either answer stands";
}

// Near an edge, fp32 tests disagree within the rounding of the coordinates: far from the
// origin a point one ulp off a shared edge is on it; near the origin the same offset is not.
TEST(Arbiter, EdgeToleranceFollowsTheCoordinatesPrecision) {
  for (float base : {0.0f, 2000.0f}) {
    TriangleMesh mesh;
    test::add_triangle(mesh, {base, base, 0}, {base + 1, base, 0}, {base + 1, base + 1, 0});
    test::add_triangle(mesh, {base, base, 0}, {base + 1, base + 1, 0}, {base, base + 1, 0});
    EmbreeScene embree(mesh, 1);
    Arbiter arbiter(mesh, embree);
    float x = base + 0.5f + 0x1p-13f, y = base + 0.5f;  // 0x1p-13: one ulp at 2000
    Ray ray = test::ray_to({x, y, 3.0f}, {x, y, 0.0f});
    EXPECT_NEAR(exact_intersect(mesh, 0, ray).min_barycentric, 0x1p-13, 1e-9);
    Verdict v = arbiter.judge(ray, test::hit_of(1, 3.0f), 0, 3.0f);  // Embree claims the neighbour
    EXPECT_FALSE(v.agree);
    if (base == 0.0f) {
      EXPECT_EQ(v.cls, MismatchClass::Unexplained);
      EXPECT_EQ(v.right, RightSide::Model);
    } else {
      EXPECT_EQ(v.cls, MismatchClass::EdgeOrVertex)
          << "edge_error " << exact_intersect(mesh, 0, ray).edge_error;
    }
  }
}

// An instance's triangle is tested in object space, the arbiter's corners are moved to the world:
// a hit 8 ulps outside an edge at 2000 is beyond a flat triangle's tolerance (about 5.5 ulps)
// but within an instance's (twice that).
TEST(Arbiter, AnInstancesEdgeToleranceCountsTheTransform) {
  InstancedMesh g;
  g.meshes.emplace_back();
  test::add_triangle(g.meshes[0], {0, 0, 0}, {1, 0, 0}, {1, 1, 0});
  test::add_triangle(g.meshes[0], {0, 0, 0}, {1, 1, 0}, {0, 1, 0});
  Transform placed;
  placed.offset = {2000.0f, 2000.0f, 0.0f};
  g.instances.push_back({0, placed});
  TriangleMesh flat = flatten(g).mesh;
  float x = 2000.5f - 8 * 0x1p-13f, y = 2000.5f;
  Ray ray = test::ray_to({x, y, 3.0f}, {x, y, 0.0f});
  EmbreeScene flat_embree(flat, 1), instanced_embree(g, 1);
  Arbiter flat_arbiter(flat, flat_embree), instanced_arbiter(FlatTriangles(g), instanced_embree);
  // The model claims triangle 0, Embree its neighbour.
  EXPECT_EQ(flat_arbiter.judge(ray, test::hit_of(1, 3.0f), 0, 3.0f).cls,
            MismatchClass::Unexplained);
  EXPECT_EQ(instanced_arbiter.judge(ray, test::hit_of(1, 3.0f), 0, 3.0f).cls,
            MismatchClass::EdgeOrVertex);
}

TEST(Arbiter, DuplicateTrianglesAreATie) {
  TriangleMesh mesh = scene();
  EmbreeScene embree(mesh, 1);
  Arbiter arbiter(mesh, embree);
  Ray ray = test::ray_to({0.75f, 0.25f, 2.0f}, {0.75f, 0.25f, 0.0f});
  Verdict v = arbiter.judge(ray, test::hit_of(0, 2.0f), 2, 2.0f);
  EXPECT_EQ(v.cls, MismatchClass::EqualTTie);
  EXPECT_EQ(v.right, RightSide::Both);
}

TEST(Arbiter, DegenerateAndGrazingAreExplained) {
  TriangleMesh mesh = scene();
  EmbreeScene embree(mesh, 1);
  Arbiter arbiter(mesh, embree);
  Ray at_line = test::ray_to({5.5f, 0.0f, 1.0f}, {5.5f, 0.0f, 0.0f});
  EXPECT_EQ(arbiter.judge(at_line, Hit{}, 3, 1.0f).cls, MismatchClass::Degenerate);
  Ray edge_on = test::ray_to({10.0f, 0.5f, -5.0f}, {10.0f, 0.5f, 5.0f});
  EXPECT_EQ(arbiter.judge(edge_on, Hit{}, 4, 5.0f).cls, MismatchClass::Grazing);
}

TEST(Arbiter, ClearDisagreementIsUnexplainedAndNamesTheRightSide) {
  TriangleMesh mesh = scene();
  EmbreeScene embree(mesh, 1);
  Arbiter arbiter(mesh, embree);
  Ray ray = test::ray_to({0.75f, 0.25f, 2.0f}, {0.75f, 0.25f, 0.0f});
  // The model misses a triangle hit squarely in its middle: Embree is right.
  Verdict missed = arbiter.judge(ray, test::hit_of(0, 2.0f), kNoHit, 0.0f);
  EXPECT_EQ(missed.cls, MismatchClass::Unexplained);
  EXPECT_EQ(missed.right, RightSide::Embree);
  // The model reports a triangle the ray does not cross, at the right t: Embree is right.
  Verdict wrong = arbiter.judge(ray, test::hit_of(0, 2.0f), 1, 2.0f);
  EXPECT_EQ(wrong.cls, MismatchClass::Unexplained);
  EXPECT_EQ(wrong.right, RightSide::Embree);
  Verdict far = arbiter.judge(ray, Hit{}, 1, 2.0f);
  EXPECT_EQ(far.cls, MismatchClass::Unexplained);
  EXPECT_EQ(far.right, RightSide::Embree);
  // Same triangle, clearly different t.
  EXPECT_EQ(arbiter.judge(ray, test::hit_of(0, 2.0f), 0, 2.5f).cls, MismatchClass::Unexplained);
}

TEST(Arbiter, AnyHitDisagreementFindsACandidate) {
  TriangleMesh mesh = scene();
  EmbreeScene embree(mesh, 1);
  Arbiter arbiter(mesh, embree);
  Ray ray = test::ray_to({0.75f, 0.25f, 2.0f}, {0.75f, 0.25f, 0.0f});
  ray.query = Query::AnyHit;
  Hit occluded = test::hit_of(kAnyPrim, ray.tmax);
  Verdict v = arbiter.judge(ray, occluded, kNoHit, 0.0f);
  EXPECT_EQ(v.cls, MismatchClass::Unexplained);
  EXPECT_EQ(v.right, RightSide::Embree);
  EXPECT_TRUE(v.disputed == 0u || v.disputed == 2u);
}

TEST(Arbiter, RangeBoundaryIsExplained) {
  TriangleMesh mesh = scene();
  EmbreeScene embree(mesh, 1);
  Arbiter arbiter(mesh, embree);
  Ray ray = test::ray_to({0.75f, 0.25f, 2.0f}, {0.75f, 0.25f, 0.0f});
  ray.tmax = 1.0f;
  EXPECT_EQ(arbiter.judge(ray, Hit{}, 0, 2.0f).cls, MismatchClass::RangeBoundary);
}

}  // namespace
}  // namespace rtsim
