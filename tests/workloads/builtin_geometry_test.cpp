// The geometry kit of the built-in scenes: the octahedron sphere is closed, consistently wound
// outward and on the unit sphere; the cube and grid quad face the right way.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "workloads/builtin_scenes.h"

namespace rtsim::builtin {
namespace {

glm::vec3 normal(const MeshTemplate& t, size_t tri) {
  const auto& i = t.triangles[tri];
  return glm::cross(t.positions[i[1]] - t.positions[i[0]], t.positions[i[2]] - t.positions[i[0]]);
}

glm::vec3 centroid(const MeshTemplate& t, size_t tri) {
  const auto& i = t.triangles[tri];
  return (t.positions[i[0]] + t.positions[i[1]] + t.positions[i[2]]) / 3.0f;
}

// Closed and consistently oriented: every directed edge appears once, its reverse once.
void expect_closed(const MeshTemplate& t) {
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (const auto& tri : t.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{tri[k], tri[(k + 1) % 3]}];
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second;
    EXPECT_EQ(directed.count({edge.second, edge.first}), 1u)
        << "open edge " << edge.first << "-" << edge.second;
  }
}

TEST(BuiltinGeometry, OctaSphereIsClosedOutwardAndUnitRadius) {
  for (int level : {1, 2, 4, 8}) {
    MeshTemplate s = octa_sphere(level);
    EXPECT_EQ(s.triangles.size(), size_t(8 * level * level)) << "level " << level;
    EXPECT_EQ(s.positions.size(), size_t(4 * level * level + 2)) << "level " << level;
    for (const auto& p : s.positions) EXPECT_NEAR(glm::length(p), 1.0f, 1e-6f);
    for (size_t t = 0; t < s.triangles.size(); ++t)
      EXPECT_GT(glm::dot(normal(s, t), centroid(s, t)), 0.0f) << "triangle " << t;
    expect_closed(s);
  }
}

TEST(BuiltinGeometry, CubeIsClosedAndOutward) {
  MeshTemplate c = unit_cube();
  ASSERT_EQ(c.triangles.size(), 12u);
  for (size_t t = 0; t < 12; ++t) EXPECT_GT(glm::dot(normal(c, t), centroid(c, t)), 0.0f);
  expect_closed(c);
}

TEST(BuiltinGeometry, GridQuadFacesUp) {
  MeshTemplate q = grid_quad(3);
  EXPECT_EQ(q.triangles.size(), 18u);
  EXPECT_EQ(q.positions.size(), 16u);
  for (size_t t = 0; t < q.triangles.size(); ++t) {
    glm::vec3 n = normal(q, t);
    EXPECT_GT(n.y, 0.0f);
    EXPECT_FLOAT_EQ(n.y, 4.0f / 9.0f) << "cells of side 2/3";
  }
}

TEST(BuiltinGeometry, RotationYIsARotation) {
  glm::mat3 r = rotation_y(0.8f, 0.6f);
  glm::vec3 x = r * glm::vec3(1, 0, 0), z = r * glm::vec3(0, 0, 1);
  EXPECT_FLOAT_EQ(x.x, 0.8f);
  EXPECT_FLOAT_EQ(x.z, -0.6f);
  EXPECT_NEAR(glm::dot(x, z), 0.0f, 1e-7f);
  EXPECT_NEAR(glm::determinant(r), 1.0f, 1e-6f);
}

}  // namespace
}  // namespace rtsim::builtin
