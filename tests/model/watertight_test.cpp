// Watertightness: 1M seeded rays from inside a closed tessellated sphere and 1M from inside a
// closed torus all hit, with the default BVH and with cwbvh8 nodes.
#include <gtest/gtest.h>

#include "model_test_util.h"
#include "workloads/hardcases.h"

namespace rtsim {
namespace {

size_t count_misses(const TriangleMesh& mesh, const std::vector<Ray>& rays, const BvhConfig& c) {
  BvhImage image = build_bvh_image(mesh, c);
  TraversalUnit unit(image);
  TraversalState state;
  size_t misses = 0;
  for (const Ray& ray : rays) misses += !unit.trace(state, ray).hit();
  return misses;
}

TEST(Watertight, MillionRaysFromInsideASphereAllHit) {
  TriangleMesh sphere = hardcases::closed_sphere({0.5f, -2.0f, 3.0f}, 2.0f, 96);
  auto rays = hardcases::rays_from_inside_sphere({0.5f, -2.0f, 3.0f}, 1.9f, 1000000, 42);
  EXPECT_EQ(count_misses(sphere, rays, BvhConfig{}), 0u);
  rays.resize(250000);
  EXPECT_EQ(count_misses(sphere, rays, test::config(NodeFormat::Cwbvh8, 8, 1)), 0u);
}

TEST(Watertight, MillionRaysFromInsideATorusAllHit) {
  TriangleMesh torus = hardcases::closed_torus({1, 2, 3}, 3.0f, 1.0f, 96, 48);
  auto rays = hardcases::rays_from_inside_torus({1, 2, 3}, 3.0f, 0.9f, 1000000, 43);
  EXPECT_EQ(count_misses(torus, rays, BvhConfig{}), 0u);
  rays.resize(250000);
  EXPECT_EQ(count_misses(torus, rays, test::config(NodeFormat::Cwbvh8, 4)), 0u);
}

}  // namespace
}  // namespace rtsim
