// Shadow pass: one any-hit ray per pixel per light, ending at the light; none where the light
// is behind the surface; a spherical light's rays stay in the cone toward it.
#include "workloads/pipeline/pass_shadow.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "tests/pipeline/test_scenes.h"
#include "workloads/pipeline/sampling.h"

namespace rtsim::pipeline {
namespace {

struct Shot {
  std::vector<Ray> rays;
  ShadowResult result;
  PassOutcome outcome;
};

Shot shoot(const test::Fixture& fx) {
  Shot shot;
  FrameContext f = fx.frame();
  GBuffer g = fx.gbuffer(f);
  RaySink sink(nullptr, fx.spec.width, fx.spec.height, false);
  sink.observer = [&](const Ray& r, PassId, uint32_t origin) {
    EXPECT_LT(origin, fx.scene.triangle_count());
    shot.rays.push_back(r);
  };
  shot.outcome = run_shadow_pass(f, g, sink, shot.result);
  return shot;
}

TEST(ShadowPass, OneRayPerPixelPerLightEndingAtThePointLight) {
  Scene s;
  test::add_wall(s, test::material("wall", 1.0f));
  test::Fixture fx(std::move(s), {test::point_light({0, 0, 3}), test::point_light({1, 1, 2})});
  Shot shot = shoot(fx);
  EXPECT_TRUE(shot.outcome.skipped.empty());
  ASSERT_EQ(shot.rays.size(), 2u * 32u * 24u);
  for (const Ray& r : shot.rays) {
    EXPECT_EQ(r.type, RayType::Shadow);
    EXPECT_EQ(r.query, Query::AnyHit);
    EXPECT_GT(r.org.z, 0.0f);  // robust origin: in front of the wall
    glm::vec3 end = r.org + r.dir * r.tmax;
    bool at_first = glm::length(end - glm::vec3(0, 0, 3)) < 1e-4f;
    bool at_second = glm::length(end - glm::vec3(1, 1, 2)) < 1e-4f;
    EXPECT_TRUE(at_first || at_second);
  }
  for (float v : shot.result.visibility) EXPECT_EQ(v, 1.0f);  // nothing in between
}

TEST(ShadowPass, LightBehindTheSurfaceGivesNoRays) {
  Scene s;
  test::add_wall(s, test::material("wall", 1.0f));
  test::Fixture fx(std::move(s), {test::point_light({0, 0, -3})});
  Shot shot = shoot(fx);
  EXPECT_TRUE(shot.rays.empty());
  EXPECT_EQ(shot.outcome.skipped, "no surface in view faces a light");
  for (float v : shot.result.visibility) EXPECT_EQ(v, -1.0f);
}

TEST(ShadowPass, NoLightsNoRays) {
  Scene s;
  test::add_wall(s, test::material("wall", 1.0f));
  test::Fixture fx(std::move(s), {});
  Shot shot = shoot(fx);
  EXPECT_TRUE(shot.rays.empty());
  EXPECT_EQ(shot.outcome.skipped, "no lights");
}

TEST(ShadowPass, OccluderBlocksTheLight) {
  Scene s;
  test::add_wall(s, test::material("wall", 1.0f));
  // A card in front of the left half of the wall; light from the upper left casts its shadow
  // onto the wall just right of x = 0.
  test::add_quad(s, {-6, -6, 1}, {0, -6, 1}, {0, 6, 1}, {-6, 6, 1}, test::material("card", 1.0f),
                 "card");
  test::Fixture fx(std::move(s), {test::point_light({-20, 0, 30})});
  Shot shot = shoot(fx);
  size_t blocked = 0, lit = 0;
  for (float v : shot.result.visibility) {
    blocked += v == 0.0f;
    lit += v == 1.0f;
  }
  EXPECT_GT(blocked, 0u);
  EXPECT_GT(lit, 0u);
}

TEST(ShadowPass, SphericalLightSamplesTheConeTowardIt) {
  Scene s;
  test::add_wall(s, test::material("wall", 1.0f));
  LightSpec sphere;
  sphere.type = LightType::Sphere;
  sphere.position = glm::vec3(0, 0, 4);
  sphere.radius = 1.0f;
  test::Fixture fx(std::move(s), {sphere});
  Shot shot = shoot(fx);
  ASSERT_EQ(shot.rays.size(), 32u * 24u);
  size_t off_centre = 0;
  for (const Ray& r : shot.rays) {
    glm::vec3 to_centre = glm::vec3(0, 0, 4) - r.org;
    float d = glm::length(to_centre);
    float cos_max = std::sqrt(1.0f - 1.0f / (d * d));
    float cos = glm::dot(r.dir, to_centre / d);
    EXPECT_GE(cos, cos_max - 1e-5f);
    off_centre += cos < 0.9999f;
    // The ray ends on the sphere's surface.
    EXPECT_NEAR(glm::length(r.org + r.dir * r.tmax - glm::vec3(0, 0, 4)), 1.0f, 1e-3f);
  }
  EXPECT_GT(off_centre, shot.rays.size() / 2);  // soft: directions spread over the cone
}

TEST(ShadowPass, SpotLightOnlyInsideItsCone) {
  Scene s;
  test::add_wall(s, test::material("wall", 1.0f));
  LightSpec spot = test::point_light({0, 0, 2});
  spot.type = LightType::Spot;
  spot.direction = glm::vec3(0, 0, -1);
  spot.cone_angle = 20.0f;
  test::Fixture fx(std::move(s), {spot});
  Shot shot = shoot(fx);
  EXPECT_GT(shot.rays.size(), 0u);
  EXPECT_LT(shot.rays.size(), 32u * 24u);
  for (const Ray& r : shot.rays)
    EXPECT_GE(glm::dot(-r.dir, glm::vec3(0, 0, -1)), std::cos(20.0f * kPi / 180.0f) - 1e-5f);
}

}  // namespace
}  // namespace rtsim::pipeline
