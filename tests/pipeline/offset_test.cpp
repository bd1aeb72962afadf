// Robust origins (Wächter & Binder): a ray leaving a triangle from the offset point never finds
// that triangle again, for triangles far from the origin, tiny, huge and at grazing angles.
#include "workloads/pipeline/offset.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "traces/embree_scene.h"
#include "workloads/pipeline/rng.h"
#include "workloads/pipeline/sampling.h"

namespace rtsim::pipeline {
namespace {

TEST(Offset, MovesToTheNormalSideByFewUlps) {
  glm::vec3 p(1000.0f, -1000.0f, 0.5f), n = glm::normalize(glm::vec3(1, 1, 1));
  glm::vec3 q = offset_ray_origin(p, n);
  EXPECT_GT(glm::dot(q - p, n), 0.0f);
  EXPECT_LT(glm::length(q - p), 1e-3f * 1000.0f);
  // Near the origin the offset is a fixed small distance along n.
  glm::vec3 z = offset_ray_origin(glm::vec3(0.0f), glm::vec3(0, 0, 1));
  EXPECT_FLOAT_EQ(z.z, 1.0f / 65536.0f);
}

TEST(Offset, HitPointAndFaceNormal) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
  m.triangles = {{0, 1, 2}};
  glm::vec3 p = hit_point(m.corners(0), 0.25f, 0.5f);
  EXPECT_FLOAT_EQ(p.x, 0.5f);
  EXPECT_FLOAT_EQ(p.y, 1.0f);
  EXPECT_EQ(face_normal(m.corners(0)), glm::vec3(0, 0, 1));
  m.positions[2] = {4, 0, 0};  // degenerate
  EXPECT_EQ(face_normal(m.corners(0)), glm::vec3(0.0f));
}

// Seeded property test: 100,000 rays leave random points of random triangles (scales 1e-3 to
// 1e4, far from the origin) into the hemisphere of the normal; none may hit its own triangle.
TEST(Offset, RaysNeverRehitTheirOwnTriangle) {
  Pcg32 r(2024);
  TriangleMesh mesh;
  const int triangles = 1000;
  for (int t = 0; t < triangles; ++t) {
    float scale = std::pow(10.0f, -3.0f + 7.0f * r.uniform());
    glm::vec3 centre = (glm::vec3(r.uniform(), r.uniform(), r.uniform()) - 0.5f) * 2e4f;
    auto base = uint32_t(mesh.positions.size());
    for (int k = 0; k < 3; ++k)
      mesh.positions.push_back(centre + scale * sample_uniform_sphere({r.uniform(), r.uniform()}));
    mesh.triangles.push_back({base, base + 1, base + 2});
  }
  EmbreeScene embree(mesh, 1);
  int self_hits = 0, rays = 0;
  for (int i = 0; i < 100000; ++i) {
    auto t = uint32_t(r.below(triangles));
    glm::vec3 n = face_normal(mesh.corners(t));
    if (n == glm::vec3(0.0f)) continue;
    float u = r.uniform(), v = r.uniform();
    if (u + v > 1.0f) {
      u = 1.0f - u;
      v = 1.0f - v;
    }
    if (r.uniform() < 0.5f) n = -n;  // leave from either side
    glm::vec3 local = sample_cosine_hemisphere({r.uniform(), r.uniform()});
    local.z = std::max(local.z, 1e-3f);  // include grazing directions
    Ray ray;
    ray.org = offset_ray_origin(hit_point(mesh.corners(t), u, v), n);
    ray.dir = glm::normalize(Basis(n).to_world(local));
    Hit hit = embree.intersect(ray);
    self_hits += hit.prim == t;
    ++rays;
  }
  EXPECT_GT(rays, 90000);
  EXPECT_EQ(self_hits, 0) << "of " << rays << " rays";
}

}  // namespace
}  // namespace rtsim::pipeline
