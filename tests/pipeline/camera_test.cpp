// Camera: directions, automatic placement (inside an enclosure, outside an object, through an
// open side) and paths over frames.
#include "workloads/pipeline/camera.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "tests/pipeline/test_scenes.h"
#include "workloads/pipeline/sampling.h"

namespace rtsim::pipeline {
namespace {

TEST(Camera, CentreRayIsForwardAndCornersSpanTheFov) {
  Camera c = Camera::look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 90.0f, 200, 100);
  glm::vec3 centre = c.direction(100.0f, 50.0f);
  EXPECT_NEAR(centre.z, -1.0f, 1e-6f);
  glm::vec3 top = c.direction(100.0f, 0.0f);
  EXPECT_NEAR(top.y, std::sqrt(0.5f), 1e-5f);  // 45 degrees up
  glm::vec3 left = c.direction(0.0f, 50.0f);
  EXPECT_LT(left.x, 0.0f);  // x = 0 is the left edge
}

// Six inward-facing walls of the box lo..hi (an interior model's room).
void add_room(Scene& s, glm::vec3 lo, glm::vec3 hi) {
  Material m = test::material("m", 1.0f);
  size_t first = s.mesh.triangles.size();
  auto quad = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    test::add_quad(s, a, b, c, d, m, "w");
  };
  quad({lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {lo.x, lo.y, hi.z});
  quad({lo.x, hi.y, lo.z}, {lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, hi.y, lo.z});
  quad({lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, lo.y, lo.z});
  quad({lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z});
  quad({lo.x, lo.y, lo.z}, {lo.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {lo.x, hi.y, lo.z});
  quad({hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {hi.x, lo.y, hi.z});
  // Winding above faces outward; an interior model faces inward.
  for (size_t t = first; t < s.mesh.triangles.size(); ++t)
    std::swap(s.mesh.triangles[t][1], s.mesh.triangles[t][2]);
}

// A 20 x 6 x 8 hall: an enclosure, so the camera goes inside and looks along the long axis.
TEST(Camera, AutoViewStandsInsideAnEnclosure) {
  Scene s;
  glm::vec3 lo(-10, 0, -4), hi(10, 6, 4);
  add_room(s, lo, hi);
  test::finish(s);
  EmbreeScene embree(s.mesh, 1);
  View v = auto_view(s.mesh, s.bounds, embree, {0, 1, 0}, 60.0f, 16.0f / 9.0f);
  EXPECT_GT(v.position.x, lo.x);
  EXPECT_LT(v.position.x, hi.x);
  EXPECT_GT(v.position.y, lo.y);
  EXPECT_LT(v.position.y, hi.y);
  EXPECT_GT(std::abs(v.look_at.x - v.position.x), 10.0f) << "looks along the long axis";
}

// A game map: two rooms in a void whose outer faces are not modelled, the centre of the bounds
// between them. The camera goes into the larger room, not outside the hull.
TEST(Camera, AutoViewFindsARoomOfALevelWhoseCentreIsInTheVoid) {
  Scene s;
  add_room(s, {-30, 0, -6}, {-10, 5, 6});  // the larger room: 20 x 5 x 12
  add_room(s, {12, 0, -3}, {22, 4, 3});
  test::finish(s);
  EmbreeScene embree(s.mesh, 1);
  View v = auto_view(s.mesh, s.bounds, embree, {0, 1, 0}, 60.0f, 16.0f / 9.0f);
  EXPECT_GT(v.position.x, -30.0f);
  EXPECT_LT(v.position.x, -10.0f);
  EXPECT_GT(v.position.y, 0.0f);
  EXPECT_LT(v.position.y, 5.0f);
  EXPECT_LT(std::abs(v.position.z), 6.0f);
  EXPECT_GT(glm::length(v.look_at - v.position), 5.0f) << "looks into the room";
}

TEST(Camera, AutoViewFitsAnObjectFromOutside) {
  Scene s;
  test::add_wall(s, test::material("m", 1.0f));
  test::finish(s);
  EmbreeScene embree(s.mesh, 1);
  View v = auto_view(s.mesh, s.bounds, embree, {0, 1, 0}, 60.0f, 1.5f);
  EXPECT_EQ(v.look_at, s.bounds.center());
  float radius = 0.5f * glm::length(s.bounds.extent());
  EXPECT_GT(glm::length(v.position - v.look_at), radius);
  // The whole bounding sphere is in view: every corner projects inside the image.
  Camera c = Camera::look_at(v.position, v.look_at, {0, 1, 0}, 60.0f, 150, 100);
  for (glm::vec3 corner : {glm::vec3(-5, -5, 0), glm::vec3(5, 5, 0)}) {
    glm::vec3 d = glm::normalize(corner - c.position);
    EXPECT_GT(glm::dot(d, c.forward), std::cos(30.0f * kPi / 180.0f) * 0.99f);
  }
}

TEST(Camera, OrbitAndKeysMoveTheCameraOverFrames) {
  CameraSpec spec;
  spec.position = glm::vec3(0, 0, 10);
  spec.look_at = glm::vec3(0, 0, 0);
  spec.orbit = 90.0f;
  View none;
  Camera first = camera_for_frame(spec, none, 0, 3, 8, 8);
  Camera last = camera_for_frame(spec, none, 2, 3, 8, 8);
  EXPECT_NEAR(first.position.z, 10.0f, 1e-5f);
  EXPECT_NEAR(last.position.x, 10.0f, 1e-4f);  // a quarter turn about +y
  EXPECT_NEAR(last.position.z, 0.0f, 1e-4f);
  spec.orbit = 0.0f;
  spec.keys = {{{0, 0, 1}, {0, 0, 0}}, {{0, 0, 3}, {0, 0, 0}}};
  EXPECT_NEAR(camera_for_frame(spec, none, 1, 3, 8, 8).position.z, 2.0f, 1e-5f);
  EXPECT_NEAR(camera_for_frame(spec, none, 2, 3, 8, 8).position.z, 3.0f, 1e-5f);
}

}  // namespace
}  // namespace rtsim::pipeline
