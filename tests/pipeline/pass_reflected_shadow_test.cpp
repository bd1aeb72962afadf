// Reflected-shadow pass: one any-hit ray per reflection hit per light.
#include "workloads/pipeline/pass_reflected_shadow.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "tests/pipeline/test_scenes.h"
#include "workloads/pipeline/pass_reflection.h"

namespace rtsim::pipeline {
namespace {

using test::RecordedRays;
using test::recording_sink;

// A glossy floor (y = -2) under the camera's view, a wall behind: reflections hit the wall,
// and every hit facing the light gets one reflected-shadow ray.
TEST(ReflectedShadowPass, OneRayPerReflectionHitPerLight) {
  Scene s;
  test::add_wall(s, test::material("wall", 1.0f));
  test::add_quad(s, {-5, -2, 0}, {-5, -2, 6}, {5, -2, 6}, {5, -2, 0}, test::material("floor", 0.2f),
                 "floor");
  test::Fixture fx(std::move(s), {test::point_light({0, 3, 3})});
  fx.spec.passes.reflection.resolution_scale = 1.0f;
  FrameContext f = fx.frame();
  GBuffer g = fx.gbuffer(f);
  RecordedRays refl_rays, shadow_rays;
  RaySink refl_sink = recording_sink(fx, refl_rays), shadow_sink = recording_sink(fx, shadow_rays);
  ReflectionResult refl;
  EXPECT_TRUE(run_reflection_pass(f, g, refl_sink, refl).skipped.empty());
  size_t floor_samples = 0;
  for (const GSample& gs : g.samples) floor_samples += gs.surface.hit() && gs.material == 1;
  EXPECT_EQ(refl.rays.size(), floor_samples);
  ReflectedShadowResult rs;
  EXPECT_TRUE(run_reflected_shadow_pass(f, g, refl, shadow_sink, rs).skipped.empty());
  size_t lit_hits = 0;
  for (const ReflectionRecord& rec : refl.rays)
    lit_hits +=
        rec.hit.hit() && glm::dot(rec.hit.normal, glm::vec3(0, 3, 3) - rec.hit.position) > 0;
  EXPECT_GT(lit_hits, 0u);
  EXPECT_EQ(shadow_rays.rays.size(), lit_hits);
  for (size_t i = 0; i < shadow_rays.rays.size(); ++i) {
    EXPECT_EQ(shadow_rays.rays[i].type, RayType::ReflectedShadow);
    EXPECT_EQ(shadow_rays.rays[i].query, Query::AnyHit);
    EXPECT_EQ(shadow_rays.origins[i] / 2, 0u) << "leaves from the wall (triangles 0, 1)";
  }
}

}  // namespace
}  // namespace rtsim::pipeline
