// Refraction pass: Snell through transmissive surfaces, nothing without glass.
#include "workloads/pipeline/pass_refraction.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "tests/pipeline/test_scenes.h"

namespace rtsim::pipeline {
namespace {

using test::RecordedRays;
using test::recording_sink;

TEST(RefractionPass, NoGlassNoRays) {
  Scene s;
  test::add_wall(s, test::material("wall", 0.1f));
  test::Fixture fx(std::move(s), {});
  FrameContext f = fx.frame();
  GBuffer g = fx.gbuffer(f);
  RecordedRays rays;
  RaySink sink = recording_sink(fx, rays);
  RefractionResult out;
  EXPECT_EQ(run_refraction_pass(f, g, sink, out).skipped, "no transmissive surface in view");
  EXPECT_TRUE(rays.rays.empty());
}

// A glass slab (front z = 0, back z = -1): smooth glass bends rays by Snell's law into the
// slab, and a second ray leaves through the back face parallel to the camera ray.
TEST(RefractionPass, SnellIntoAndOutOfASlab) {
  Scene s;
  Material glass = test::material("glass", 0.0f);
  glass.transmission = 1.0f;
  glass.ior = 1.5f;
  test::add_wall(s, glass, "front");
  test::add_quad(s, {-5, -5, -1}, {-5, 5, -1}, {5, 5, -1}, {5, -5, -1}, glass, "back");
  test::Fixture fx(std::move(s), {});
  FrameContext f = fx.frame();
  GBuffer g = fx.gbuffer(f);
  RecordedRays rays;
  RaySink sink = recording_sink(fx, rays);
  RefractionResult out;
  EXPECT_TRUE(run_refraction_pass(f, g, sink, out).skipped.empty());
  ASSERT_EQ(rays.rays.size(), 2u * 32u * 24u);
  for (size_t i = 0; i < rays.rays.size(); i += 2) {
    const GSample& gs = g.samples[i / 2];
    const Ray& in = rays.rays[i];
    const Ray& out_ray = rays.rays[i + 1];
    EXPECT_EQ(in.type, RayType::Refraction);
    EXPECT_LT(in.org.z, 0.0f) << "pushed inside the slab";
    float sin_i = glm::length(glm::cross(gs.view, glm::vec3(0, 0, 1)));
    float sin_t = glm::length(glm::cross(in.dir, glm::vec3(0, 0, 1)));
    EXPECT_NEAR(sin_t, sin_i / 1.5f, 1e-4f);
    EXPECT_LT(out_ray.org.z, -1.0f) << "pushed out through the back";
    EXPECT_NEAR(glm::dot(out_ray.dir, gs.view), 1.0f, 1e-4f);
  }
}

}  // namespace
}  // namespace rtsim::pipeline
