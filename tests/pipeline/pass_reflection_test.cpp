// Reflection pass: a quarter ray per pixel from glossy surfaces, GGX directions above the
// horizon (re-rolled), Halton with per-pixel rotation, stochastic layer choice.
#include "workloads/pipeline/pass_reflection.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "tests/pipeline/test_scenes.h"
#include "workloads/pipeline/sampling.h"

namespace rtsim::pipeline {
namespace {

std::vector<Ray> shoot(const test::Fixture& fx, ReflectionResult& out, PassOutcome& outcome,
                       uint32_t frame = 0) {
  std::vector<Ray> rays;
  FrameContext f = fx.frame(frame);
  GBuffer g = fx.gbuffer(f);
  RaySink sink(nullptr, fx.spec.width, fx.spec.height, false);
  sink.observer = [&](const Ray& r, PassId, uint32_t) { rays.push_back(r); };
  outcome = run_reflection_pass(f, g, sink, out);
  return rays;
}

TEST(ReflectionPass, QuarterRayPerPixelOnGlossySurfaces) {
  Scene s;
  test::add_wall(s, test::material("glossy", 0.3f));
  test::Fixture fx(std::move(s), {});
  ReflectionResult out;
  PassOutcome outcome;
  std::vector<Ray> rays = shoot(fx, out, outcome);
  EXPECT_EQ(rays.size(), 32u * 24u / 4u);
  EXPECT_EQ(out.rays.size(), rays.size());
  for (const Ray& r : rays) {
    EXPECT_EQ(r.type, RayType::Reflection);
    EXPECT_EQ(r.query, Query::ClosestHit);
    EXPECT_GT(r.dir.z, 0.0f);  // above the wall
    EXPECT_GT(r.org.z, 0.0f);
  }
  for (const ReflectionRecord& rec : out.rays) EXPECT_GT(rec.pdf, 0.0f);
}

TEST(ReflectionPass, RoughSurfacesGetNone) {
  Scene s;
  test::add_wall(s, test::material("rough", 0.9f));
  test::Fixture fx(std::move(s), {});
  ReflectionResult out;
  PassOutcome outcome;
  EXPECT_TRUE(shoot(fx, out, outcome).empty());
  EXPECT_EQ(outcome.skipped, "no glossy surface in view (roughness <= reflection.max_roughness)");
}

TEST(ReflectionPass, SameFrameSameRaysNextFrameOtherRays) {
  Scene s;
  test::add_wall(s, test::material("glossy", 0.4f));
  test::Fixture fx(std::move(s), {});
  ReflectionResult out;
  PassOutcome outcome;
  std::vector<Ray> a = shoot(fx, out, outcome, 1), b = shoot(fx, out, outcome, 1);
  std::vector<Ray> c = shoot(fx, out, outcome, 2);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(a[i] == b[i]);
  size_t same = 0;
  for (size_t i = 0; i < std::min(a.size(), c.size()); ++i) same += a[i].dir == c[i].dir;
  EXPECT_EQ(same, 0u);
}

// At a grazing view most GGX samples of a rough lobe fall below the horizon; every direction
// returned is above it, and re-rolls are counted.
TEST(ReflectionSampling, ReRollsBelowTheHorizon) {
  ShadingMaterial m;
  m.roughness = 0.5f;
  glm::vec3 n(0, 0, 1), v = glm::normalize(glm::vec3(1.0f, 0.0f, 0.05f));
  LayerStack stack = layer_stack(m, glm::dot(v, n));
  uint32_t total_rerolls = 0;
  for (uint32_t i = 1; i < 200; ++i) {
    uint32_t rerolls = 0;
    glm::vec3 l = sample_reflection(stack, 0, v, n, i, {0.3f, 0.7f}, 8, rerolls);
    EXPECT_GE(l.z, 0.0f);
    EXPECT_NEAR(glm::length(l), 1.0f, 1e-5f);
    total_rerolls += rerolls;
  }
  EXPECT_GT(total_rerolls, 0u);
}

// Cranley-Patterson rotation: two pixels with different rotations get different directions
// from the same Halton index, and a rotation of 0 reproduces the plain Halton point.
TEST(ReflectionSampling, RotationDecorrelatesPixels) {
  ShadingMaterial m;
  m.roughness = 0.4f;
  glm::vec3 n(0, 0, 1), v(0, 0, 1);
  LayerStack stack = layer_stack(m, 1.0f);
  uint32_t rerolls = 0;
  glm::vec3 a = sample_reflection(stack, 0, v, n, 5, {0.0f, 0.0f}, 8, rerolls);
  glm::vec3 b = sample_reflection(stack, 0, v, n, 5, {0.5f, 0.25f}, 8, rerolls);
  EXPECT_NE(a, b);
  glm::vec3 h = sample_ggx_half_vector({halton(5, 2), halton(5, 3)}, stack.alpha[0]);
  glm::vec3 expected = glm::normalize(Basis(n).to_world(reflect_dir(-v, h)));
  EXPECT_NEAR(glm::length(a - expected), 0.0f, 1e-5f);
}

TEST(Layers, SchlickVisibilityFavoursTheCoatAtGrazingAngles) {
  ShadingMaterial m;
  m.layers = 2;
  m.roughness = 0.6f;
  m.coat_roughness = 0.05f;
  LayerStack head_on = layer_stack(m, 1.0f), grazing = layer_stack(m, 0.1f);
  EXPECT_NEAR(head_on.probability[0] + head_on.probability[1], 1.0f, 1e-6f);
  EXPECT_GT(grazing.probability[0], head_on.probability[0]);
  // Head-on, coat and base both reflect F0 = 0.04, and the base sees 1 - 0.04 of the light:
  // the coat's share is 0.04 / (0.04 + 0.96 * 0.04).
  EXPECT_NEAR(head_on.probability[0], 1.0f / (2.0f - 0.04f), 1e-3f);
  EXPECT_EQ(choose_layer(head_on, 0.0f), 0);
  EXPECT_EQ(choose_layer(head_on, 0.999f), 1);
  // The direction's density sums over the layers.
  glm::vec3 v(0, 0, 1), l = glm::normalize(glm::vec3(0.1f, 0.0f, 1.0f));
  float sum = head_on.probability[0] * ggx_reflection_pdf(v, l, head_on.alpha[0]) +
              head_on.probability[1] * ggx_reflection_pdf(v, l, head_on.alpha[1]);
  EXPECT_FLOAT_EQ(stack_pdf(head_on, v, l), sum);
}

TEST(ReflectionPass, LayeredRoughBaseStillReflectsThroughItsCoat) {
  Scene s;
  Material coated = test::material("coated", 0.9f);
  coated.layers = 2;
  s.materials.clear();
  test::add_wall(s, coated);
  test::Fixture fx(std::move(s), {});
  ReflectionResult out;
  PassOutcome outcome;
  std::vector<Ray> rays = shoot(fx, out, outcome);
  EXPECT_EQ(rays.size(), 32u * 24u / 4u);
  size_t coat = 0;
  for (const ReflectionRecord& rec : out.rays) coat += rec.layer == 0;
  EXPECT_GT(coat, 0u);
  EXPECT_LT(coat, out.rays.size());
}

}  // namespace
}  // namespace rtsim::pipeline
