// Camera sample placement: regular with TAA jitter, and irregular by an importance map
// (Harada & Fujita 2014) with an exact total.
#include "workloads/pipeline/samples.h"

#include <gtest/gtest.h>

#include "workloads/pipeline/gbuffer.h"

namespace rtsim::pipeline {
namespace {

TEST(Samples, RegularIsOnePerPixelWithTheFrameJitter) {
  glm::vec2 j0 = frame_jitter(0, true), j1 = frame_jitter(1, true);
  EXPECT_NE(j0, j1);
  EXPECT_EQ(frame_jitter(5, false), glm::vec2(0.0f));
  std::vector<SamplePosition> s = regular_samples(4, 3, j0);
  ASSERT_EQ(s.size(), 12u);
  EXPECT_EQ(s[5].pixel, 5u);
  EXPECT_FLOAT_EQ(s[5].sx, 1.5f + j0.x);
  EXPECT_FLOAT_EQ(s[5].sy, 1.5f + j0.y);
}

TEST(Samples, ImportancePlacesExactlyTheCountMostWhereImportant) {
  const uint32_t w = 64, h = 32;
  std::vector<float> importance(w * h, 0.0f);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 48; x < 64; ++x) importance[y * w + x] = 1.0f;  // right quarter
  std::vector<SamplePosition> s = importance_samples(w, h, 5000, importance, 0.2f, 1, 0);
  ASSERT_EQ(s.size(), 5000u);
  size_t right = 0;
  for (const SamplePosition& p : s) {
    ASSERT_LT(p.pixel, w * h);
    EXPECT_EQ(uint32_t(p.sx), p.pixel % w);  // the position lies in its pixel
    EXPECT_EQ(uint32_t(p.sy), p.pixel / w);
    right += p.pixel % w >= 48;
  }
  // 80% by importance (all on the right) + 20% uniform (a quarter of which on the right).
  EXPECT_NEAR(double(right) / 5000.0, 0.8 + 0.2 * 0.25, 0.01);
  // Sample indices count up within each pixel.
  for (size_t i = 1; i < s.size(); ++i) {
    if (s[i].pixel == s[i - 1].pixel) {
      EXPECT_EQ(s[i].index, s[i - 1].index + 1);
    }
  }
  // Deterministic.
  std::vector<SamplePosition> again = importance_samples(w, h, 5000, importance, 0.2f, 1, 0);
  for (size_t i = 0; i < s.size(); ++i) EXPECT_EQ(s[i].sx, again[i].sx);
}

TEST(Samples, ZeroImportanceFallsBackToUniform) {
  std::vector<float> importance(100, 0.0f);
  std::vector<SamplePosition> s = importance_samples(10, 10, 100, importance, 0.0f, 1, 0);
  ASSERT_EQ(s.size(), 100u);
  for (size_t i = 0; i < 100; ++i) EXPECT_EQ(s[i].pixel, i);
}

TEST(Samples, EdgesAndCostRaiseImportance) {
  GBuffer g;
  g.width = 8;
  g.height = 1;
  for (uint32_t p = 0; p < 8; ++p) {
    GSample s;
    s.pixel = p;
    s.surface.prim = 0;
    s.depth = p < 4 ? 1.0f : 10.0f;  // a depth edge between pixels 3 and 4
    s.surface.normal = glm::vec3(0, 0, 1);
    g.samples.push_back(s);
  }
  SampleSpec spec;
  spec.cost = false;
  std::vector<float> edges = importance_map(g, {}, spec);
  EXPECT_GT(edges[3], 0.0f);
  EXPECT_GT(edges[4], 0.0f);
  EXPECT_EQ(edges[0], 0.0f);
  EXPECT_EQ(edges[7], 0.0f);
  spec.edges = false;
  spec.cost = true;
  std::vector<float> cost = importance_map(g, {1, 1, 1, 1, 1, 1, 1, 9}, spec);
  EXPECT_GT(cost[7], 5.0f * cost[0]);
}

}  // namespace
}  // namespace rtsim::pipeline
