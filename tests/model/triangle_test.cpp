// Ray-triangle unit: the watertight test of Woop, Benthin & Wald and the Woop unit test.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "model/units/prepared_ray.h"
#include "model/units/ray_triangle.h"

namespace rtsim {
namespace {

PreparedRay prepare(glm::vec3 org, glm::vec3 dir, float tmin = 0.0f,
                    float tmax = std::numeric_limits<float>::infinity()) {
  Ray r;
  r.org = org;
  r.dir = dir;
  r.tmin = tmin;
  r.tmax = tmax;
  return prepare_ray(r, 10.0f, 0x1p-20f);
}

const float kUnit[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};  // right triangle in z = 0

TEST(Watertight, HitsInteriorWithExactDistanceAndBarycentrics) {
  TriangleHit hit;
  PreparedRay ray = prepare({0.25f, 0.25f, 2.0f}, {0, 0, -1});
  ASSERT_TRUE(intersect_watertight(ray, kUnit, 0.0f, ray.tmax, hit));
  EXPECT_EQ(hit.t, 2.0f);
  EXPECT_FLOAT_EQ(hit.u, 0.25f);
  EXPECT_FLOAT_EQ(hit.v, 0.25f);
}

TEST(Watertight, BackfacesHitAndOutsideMisses) {
  TriangleHit hit;
  PreparedRay below = prepare({0.25f, 0.25f, -2.0f}, {0, 0, 1});
  EXPECT_TRUE(intersect_watertight(below, kUnit, 0.0f, below.tmax, hit));
  PreparedRay outside = prepare({0.75f, 0.75f, 2.0f}, {0, 0, -1});
  EXPECT_FALSE(intersect_watertight(outside, kUnit, 0.0f, outside.tmax, hit));
}

TEST(Watertight, RangeIsInclusiveAndTight) {
  TriangleHit hit;
  PreparedRay ray = prepare({0.25f, 0.25f, 2.0f}, {0, 0, -1});
  EXPECT_TRUE(intersect_watertight(ray, kUnit, 0.0f, 2.0f, hit));
  EXPECT_FALSE(intersect_watertight(ray, kUnit, 0.0f, std::nextafter(2.0f, 0.0f), hit));
  EXPECT_FALSE(intersect_watertight(ray, kUnit, std::nextafter(2.0f, 3.0f), 5.0f, hit));
}

TEST(Watertight, SharedEdgeAndVertexAlwaysHitOneOfTheTriangles) {
  // A quad split along its diagonal; rays through points of the diagonal and the corners.
  const float first[9] = {0, 0, 0, 1, 0, 0, 1, 1, 0};
  const float second[9] = {0, 0, 0, 1, 1, 0, 0, 1, 0};
  int misses = 0;
  for (int i = 0; i <= 1000; ++i) {
    float s = float(i) / 1000.0f;
    for (glm::vec3 org : {glm::vec3(0.3f, -0.7f, 3.0f), glm::vec3(-2.0f, 1.5f, -1.0f)}) {
      glm::vec3 target(s, s, 0.0f);
      PreparedRay ray = prepare(org, target - org);
      TriangleHit hit;
      bool any = intersect_watertight(ray, first, 0.0f, ray.tmax, hit) ||
                 intersect_watertight(ray, second, 0.0f, ray.tmax, hit);
      misses += !any;
    }
  }
  EXPECT_EQ(misses, 0);
}

TEST(Watertight, DegenerateTrianglesNeverHit) {
  const float line[9] = {0, 0, 0, 1, 0, 0, 2, 0, 0};
  const float point[9] = {1, 1, 0, 1, 1, 0, 1, 1, 0};
  TriangleHit hit;
  for (glm::vec3 target : {glm::vec3(0.5f, 0, 0), glm::vec3(1, 1, 0), glm::vec3(1, 0, 0)}) {
    PreparedRay ray = prepare(target + glm::vec3(0.1f, 0.2f, 1.0f), {-0.1f, -0.2f, -1.0f});
    EXPECT_FALSE(intersect_watertight(ray, line, 0.0f, ray.tmax, hit));
    EXPECT_FALSE(intersect_watertight(ray, point, 0.0f, ray.tmax, hit));
  }
}

TEST(Watertight, DenormalAndSignedZeroDirections) {
  const float wall[9] = {10, -5, -5, 10, 5, -5, 10, 0, 5};
  TriangleHit hit;
  for (glm::vec3 dir : {glm::vec3(1, 0, -0.0f), glm::vec3(1, 1e-40f, -1e-42f),
                        glm::vec3(1e-39f, 0, 0), glm::vec3(1, -0.0f, 0)}) {
    PreparedRay ray = prepare({9.999f, 0, 0}, dir);
    ASSERT_TRUE(intersect_watertight(ray, wall, 0.0f, ray.tmax, hit)) << dir.x;
    EXPECT_NEAR(std::ldexp(hit.t, ray.t_exponent) * dir.x, 10.0f - 9.999f, 1e-7f);
  }
}

TEST(Watertight, TLimitEndsHitsWhereTOverflows) {
  // Direction (1e-45, 0, 0): the wall 0.001 away is at t = 7e41, beyond every float (Embree
  // misses); 1e-39 brings it to t = 1e36, a float. The traversal tests up to t_limit.
  const float wall[9] = {10, -5, -5, 10, 5, -5, 10, 0, 5};
  TriangleHit hit;
  PreparedRay ray = prepare({9.999f, 0, 0}, {1e-45f, 0, 0});
  ASSERT_TRUE(intersect_watertight(ray, wall, 0.0f, ray.tmax, hit));
  EXPECT_EQ(std::ldexp(hit.t, ray.t_exponent), std::numeric_limits<float>::infinity());
  EXPECT_FALSE(intersect_watertight(ray, wall, 0.0f, ray.t_limit, hit)) << hit.t;
  ray = prepare({9.999f, 0, 0}, {1e-39f, 0, 0});
  ASSERT_TRUE(intersect_watertight(ray, wall, 0.0f, ray.t_limit, hit));
  EXPECT_TRUE(std::isfinite(std::ldexp(hit.t, ray.t_exponent)));
  EXPECT_EQ(prepare({0, 0, 0}, {1, 0, 0}).t_limit, std::numeric_limits<float>::infinity());
}

TEST(Woop, AgreesWithWatertightAwayFromEdges) {
  // Rows of the unit-triangle map of kUnit: u = x, v = y, z = z.
  const float rows[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  for (float x : {0.1f, 0.3f, 0.6f})
    for (float y : {0.1f, 0.3f, 0.6f}) {
      PreparedRay ray = prepare({x, y, 3.0f}, {0, 0, -1});
      TriangleHit a, b;
      bool wt = intersect_watertight(ray, kUnit, 0.0f, ray.tmax, a);
      bool wo = intersect_woop(ray, rows, 0.0f, ray.tmax, b);
      EXPECT_EQ(wt, wo) << x << " " << y;
      if (wt && wo) {
        EXPECT_FLOAT_EQ(a.t, b.t);
      }
    }
}

}  // namespace
}  // namespace rtsim
