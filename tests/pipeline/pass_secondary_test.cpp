// Reflected shadows, AO, refraction and translucency passes on hand-made scenes.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "tests/pipeline/test_scenes.h"
#include "workloads/pipeline/pass_ao.h"
#include "workloads/pipeline/pass_reflected_shadow.h"
#include "workloads/pipeline/pass_reflection.h"
#include "workloads/pipeline/pass_refraction.h"
#include "workloads/pipeline/pass_translucency.h"

namespace rtsim::pipeline {
namespace {

struct Rays {
  std::vector<Ray> rays;
  std::vector<uint32_t> origins;
};

RaySink recording_sink(const test::Fixture& fx, Rays& out) {
  RaySink sink(nullptr, fx.spec.width, fx.spec.height, false);
  sink.observer = [&out](const Ray& r, PassId, uint32_t origin) {
    out.rays.push_back(r);
    out.origins.push_back(origin);
  };
  return sink;
}

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
  Rays refl_rays, shadow_rays;
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

TEST(AoPass, ShortAnyHitRaysAtHalfResolution) {
  Scene s;
  test::add_wall(s, test::material("wall", 1.0f));
  test::Fixture fx(std::move(s), {});
  fx.spec.passes.ao.radius = 0.5f;
  FrameContext f = fx.frame();
  GBuffer g = fx.gbuffer(f);
  Rays rays;
  RaySink sink = recording_sink(fx, rays);
  AoResult ao;
  EXPECT_TRUE(run_ao_pass(f, g, sink, ao).skipped.empty());
  ASSERT_EQ(rays.rays.size(), 32u * 24u / 4u);
  for (const Ray& r : rays.rays) {
    EXPECT_EQ(r.type, RayType::AO);
    EXPECT_EQ(r.query, Query::AnyHit);
    EXPECT_FLOAT_EQ(r.tmax, 0.5f);
    EXPECT_GE(r.dir.z, 0.0f);
  }
  for (float v : ao.visibility) EXPECT_EQ(v, 1.0f);  // a flat wall occludes nothing
}

TEST(RefractionPass, NoGlassNoRays) {
  Scene s;
  test::add_wall(s, test::material("wall", 0.1f));
  test::Fixture fx(std::move(s), {});
  FrameContext f = fx.frame();
  GBuffer g = fx.gbuffer(f);
  Rays rays;
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
  Rays rays;
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

TEST(TranslucencyPass, InnerHemisphereFromAPushedInOrigin) {
  Scene s;
  Material jade = test::material("jade", 0.5f);
  jade.translucency = 0.5f;
  test::add_wall(s, jade);
  test::Fixture fx(std::move(s), {});
  FrameContext f = fx.frame();
  GBuffer g = fx.gbuffer(f);
  Rays rays;
  RaySink sink = recording_sink(fx, rays);
  TranslucencyResult out;
  EXPECT_TRUE(run_translucency_pass(f, g, sink, out).skipped.empty());
  ASSERT_EQ(rays.rays.size(), 32u * 24u / 4u);
  double mean_z = 0.0;
  for (const Ray& r : rays.rays) {
    EXPECT_EQ(r.type, RayType::Translucency);
    EXPECT_LT(r.org.z, 0.0f);
    EXPECT_LE(r.dir.z, 0.0f);
    mean_z += r.dir.z;
  }
  // Uniform over the inner hemisphere: mean cosine 1/2.
  EXPECT_NEAR(mean_z / double(rays.rays.size()), -0.5, 0.05);
}

}  // namespace
}  // namespace rtsim::pipeline
