// Ray validation, type names, hashing and mesh helpers.
#include <gtest/gtest.h>

#include <cmath>

#include "traces/hash.h"
#include "traces/ray.h"

namespace rtsim {
namespace {

TEST(RayProblem, AcceptsInfiniteTmaxAndDenormalDirections) {
  Ray ray;
  ray.dir = {1e-40f, -0.0f, 0.0f};
  ray.tmax = std::numeric_limits<float>::infinity();
  EXPECT_EQ(ray_problem(ray), "");
}

TEST(RayProblem, RejectsEachBadField) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  auto problem = [](auto edit) {
    Ray ray;
    edit(ray);
    return ray_problem(ray);
  };
  EXPECT_EQ(problem([&](Ray& r) { r.org.x = inf; }), "origin is NaN or Inf");
  EXPECT_EQ(problem([&](Ray& r) { r.dir.z = nan; }), "direction is NaN or Inf");
  EXPECT_EQ(problem([&](Ray& r) { r.dir = glm::vec3(0.0f); }), "direction is zero");
  EXPECT_EQ(problem([&](Ray& r) { r.org.y = -1.9e18f; }),
            "an origin component is beyond +-1.844e18 (Embree's range)");
  EXPECT_EQ(problem([&](Ray& r) { r.dir.x = 2e18f; }),
            "a direction component is beyond +-1.844e18 (Embree's range)");
  EXPECT_EQ(problem([&](Ray& r) { r.org.z = 1.8e18f; }), "") << "inside the range";
  EXPECT_EQ(problem([&](Ray& r) { r.tmin = nan; }), "tmin is NaN or Inf");
  EXPECT_EQ(problem([&](Ray& r) { r.tmax = nan; }), "tmax is NaN or -Inf");
  EXPECT_EQ(problem([&](Ray& r) { r.tmin = -1.0f; }), "tmin is negative");
  EXPECT_EQ(problem([&](Ray& r) { r.tmin = 2.0f, r.tmax = 1.0f; }), "tmin is greater than tmax");
  EXPECT_EQ(problem([&](Ray& r) { r.type = RayType(8); }), "unknown ray type");
  EXPECT_EQ(problem([&](Ray& r) { r.query = Query(2); }), "unknown query");
}

TEST(RayType, NamesRoundTrip) {
  for (int t = 0; t < kRayTypeCount; ++t) {
    auto type = static_cast<RayType>(t);
    EXPECT_EQ(ray_type_from_name(ray_type_name(type)), type);
  }
  EXPECT_EQ(ray_type_from_name("gi"), std::nullopt);
  EXPECT_STREQ(ray_type_name(RayType::ReflectedShadow), "reflected_shadow");
}

TEST(Hash, Crc32MatchesTheStandardCheckValue) {
  EXPECT_EQ(crc32("123456789", 9), 0xcbf43926u);
}

TEST(Hash, FingerprintChangesWithAnyVertexBit) {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}};
  uint64_t a = mesh_fingerprint(mesh);
  EXPECT_EQ(a, mesh_fingerprint(mesh));
  mesh.positions[2].y = std::nextafter(1.0f, 2.0f);
  EXPECT_NE(a, mesh_fingerprint(mesh));
  mesh.positions[2].y = 1.0f;
  mesh.triangles[0] = {0, 2, 1};
  EXPECT_NE(a, mesh_fingerprint(mesh));
}

TEST(Bounds, GrowAndSurfaceArea) {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {2, 0, 0}, {0, 3, 4}};
  mesh.triangles = {{0, 1, 2}};
  Bounds b = mesh_bounds(mesh);
  EXPECT_EQ(b.lo, glm::vec3(0, 0, 0));
  EXPECT_EQ(b.hi, glm::vec3(2, 3, 4));
  EXPECT_FLOAT_EQ(b.surface_area(), 2.0f * (6 + 12 + 8));
  EXPECT_TRUE(Bounds().empty());
  EXPECT_EQ(Bounds().surface_area(), 0.0f);
}

}  // namespace
}  // namespace rtsim
