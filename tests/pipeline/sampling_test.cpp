// Samplers: determinism, ranges and first moments (seeded Monte Carlo, fixed seeds).
#include "workloads/pipeline/sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "workloads/pipeline/rng.h"

namespace rtsim::pipeline {
namespace {

TEST(Rng, SameSeedSameSequenceAndStreamsDiffer) {
  Pcg32 a(42, 1), b(42, 1), c(42, 2);
  int same_as_other_stream = 0;
  for (int i = 0; i < 1000; ++i) {
    uint32_t x = a.next();
    EXPECT_EQ(x, b.next());
    same_as_other_stream += x == c.next();
  }
  EXPECT_LT(same_as_other_stream, 3);
  Pcg32 d = make_rng(7, RngStream::Shadow, 3, 99), e = make_rng(7, RngStream::Shadow, 3, 99);
  EXPECT_EQ(d.next(), e.next());
}

TEST(Rng, UniformIsInUnitIntervalWithMeanHalf) {
  Pcg32 r(1);
  double sum = 0.0;
  for (int i = 0; i < 100000; ++i) {
    float u = r.uniform();
    ASSERT_GE(u, 0.0f);
    ASSERT_LT(u, 1.0f);
    sum += u;
  }
  EXPECT_NEAR(sum / 100000.0, 0.5, 0.005);
  uint32_t counts[3] = {};
  for (int i = 0; i < 30000; ++i) counts[r.below(3)]++;
  for (uint32_t c : counts) EXPECT_NEAR(c, 10000, 400);
}

TEST(Halton, FirstPointsOfBases2And3) {
  EXPECT_FLOAT_EQ(halton(1, 2), 0.5f);
  EXPECT_FLOAT_EQ(halton(2, 2), 0.25f);
  EXPECT_FLOAT_EQ(halton(3, 2), 0.75f);
  EXPECT_FLOAT_EQ(halton(1, 3), 1.0f / 3.0f);
  EXPECT_FLOAT_EQ(halton(2, 3), 2.0f / 3.0f);
  EXPECT_FLOAT_EQ(halton(3, 3), 1.0f / 9.0f);
  EXPECT_LT(halton(0xffffffffu, 2), 1.0f);
}

TEST(CranleyPatterson, ShiftsModuloOne) {
  glm::vec2 r = cranley_patterson({0.75f, 0.25f}, {0.5f, 0.5f});
  EXPECT_FLOAT_EQ(r.x, 0.25f);
  EXPECT_FLOAT_EQ(r.y, 0.75f);
  r = cranley_patterson({0.999f, 0.0f}, {0.001f, 0.0f});
  EXPECT_LT(r.x, 1.0f);
}

TEST(Basis, IsOrthonormalForManyNormals) {
  Pcg32 r(3);
  for (int i = 0; i < 1000; ++i) {
    glm::vec3 n = sample_uniform_sphere({r.uniform(), r.uniform()});
    Basis b(n);
    EXPECT_NEAR(glm::dot(b.t, b.b), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(b.t, n), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(b.t), 1.0f, 1e-5f);
    glm::vec3 w = b.to_world({0.3f, -0.2f, 0.9f});
    glm::vec3 back = b.to_local(w);
    EXPECT_NEAR(back.x, 0.3f, 1e-5f);
    EXPECT_NEAR(back.z, 0.9f, 1e-5f);
  }
}

TEST(Hemisphere, CosineWeightedHasMeanCosineTwoThirds) {
  Pcg32 r(5);
  double sum = 0.0;
  for (int i = 0; i < 200000; ++i) {
    glm::vec3 d = sample_cosine_hemisphere({r.uniform(), r.uniform()});
    ASSERT_GE(d.z, 0.0f);
    ASSERT_NEAR(glm::length(d), 1.0f, 1e-4f);
    sum += d.z;
  }
  EXPECT_NEAR(sum / 200000.0, 2.0 / 3.0, 0.003);
}

TEST(Sphere, UniformHasZeroMeanAndUnitLength) {
  Pcg32 r(6);
  glm::dvec3 sum(0.0);
  for (int i = 0; i < 200000; ++i) {
    glm::vec3 d = sample_uniform_sphere({r.uniform(), r.uniform()});
    ASSERT_NEAR(glm::length(d), 1.0f, 1e-4f);
    sum += glm::dvec3(d);
  }
  EXPECT_LT(glm::length(sum / 200000.0), 0.01);
}

TEST(Cone, StaysInsideAndIsUniformInCosine) {
  Pcg32 r(7);
  const float cos_max = 0.9f;
  double sum = 0.0;
  for (int i = 0; i < 100000; ++i) {
    glm::vec3 d = sample_uniform_cone({r.uniform(), r.uniform()}, cos_max);
    ASSERT_GE(d.z, cos_max - 1e-6f);
    sum += d.z;
  }
  EXPECT_NEAR(sum / 100000.0, (1.0 + cos_max) / 2.0, 0.001);
}

// The sampled reflection density integrates to the share of directions above the horizon.
TEST(Ggx, ReflectionPdfMatchesSampledHistogram) {
  const float alpha = 0.3f;
  glm::vec3 v = glm::normalize(glm::vec3(0.3f, 0.0f, 1.0f));
  Pcg32 r(8);
  int n = 400000, in_cap = 0;
  for (int i = 0; i < n; ++i) {
    glm::vec3 h = sample_ggx_half_vector({r.uniform(), r.uniform()}, alpha);
    glm::vec3 l = reflect_dir(-v, h);
    in_cap += glm::dot(l, reflect_dir(-v, {0, 0, 1})) > 0.99f;
  }
  // Integrate the pdf over the same cap (cos > 0.99 around the mirror direction).
  glm::vec3 mirror = reflect_dir(-v, {0, 0, 1});
  Basis b(mirror);
  double integral = 0.0;
  const int steps = 200;
  for (int i = 0; i < steps; ++i)
    for (int j = 0; j < steps; ++j) {
      double cos_t = 1.0 - 0.01 * (i + 0.5) / steps;
      double phi = 2.0 * kPi * (j + 0.5) / steps;
      double sin_t = std::sqrt(1.0 - cos_t * cos_t);
      glm::vec3 l = b.to_world(glm::vec3(sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t));
      integral += ggx_reflection_pdf(v, l, alpha) * (0.01 / steps) * (2.0 * kPi / steps);
    }
  EXPECT_NEAR(double(in_cap) / n, integral, 0.01);
}

TEST(Fresnel, SchlickEndsAndSnell) {
  EXPECT_NEAR(dielectric_f0(1.5f), 0.04f, 1e-6f);
  EXPECT_FLOAT_EQ(schlick(0.04f, 1.0f), 0.04f);
  EXPECT_FLOAT_EQ(schlick(0.04f, 0.0f), 1.0f);
  glm::vec3 out;
  glm::vec3 in = glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f));
  ASSERT_TRUE(refract_dir(in, {0, 1, 0}, 1.0f / 1.5f, out));
  // Snell: sin(theta_t) = sin(45 deg) / 1.5.
  EXPECT_NEAR(out.x, std::sin(kPi / 4.0f) / 1.5f, 1e-5f);
  EXPECT_FALSE(refract_dir(in, {0, 1, 0}, 1.5f, out));  // total internal reflection
}

}  // namespace
}  // namespace rtsim::pipeline
