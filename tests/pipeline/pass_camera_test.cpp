// Camera pass and G-buffer: one ray per sample, hits filled from Embree, cell selection for
// passes at reduced resolution.
#include "workloads/pipeline/pass_camera.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "tests/pipeline/test_scenes.h"

namespace rtsim::pipeline {
namespace {

TEST(CameraPass, FillsTheGBufferAndEmitsOneRayPerSample) {
  Scene s;
  test::add_wall(s, test::material("wall", 0.7f));
  test::Fixture fx(std::move(s), {});
  FrameContext f = fx.frame(3);
  RaySink sink(nullptr, 32, 24, true);
  std::vector<Ray> rays;
  sink.observer = [&](const Ray& r, PassId pass, uint32_t origin) {
    EXPECT_EQ(pass, PassId::Camera);
    EXPECT_EQ(origin, kNoHit);
    rays.push_back(r);
  };
  GBuffer g = run_camera_pass(f, regular_samples(32, 24, {0, 0}), &sink);
  ASSERT_EQ(g.samples.size(), 32u * 24u);
  ASSERT_EQ(rays.size(), 32u * 24u);
  for (size_t i = 0; i < g.samples.size(); ++i) {
    const GSample& gs = g.samples[i];
    ASSERT_TRUE(gs.surface.hit());
    EXPECT_EQ(gs.pixel, i);
    EXPECT_EQ(rays[i].pixel, i);
    EXPECT_EQ(rays[i].frame, 3u);
    EXPECT_EQ(rays[i].type, RayType::Camera);
    EXPECT_EQ(rays[i].query, Query::ClosestHit);
    EXPECT_NEAR(gs.surface.position.z, 0.0f, 1e-6f);
    EXPECT_EQ(gs.surface.normal, glm::vec3(0, 0, 1));  // faces the camera
    EXPECT_TRUE(gs.surface.front);
    EXPECT_NEAR(gs.depth, glm::length(gs.surface.position - f.camera.position), 1e-4f);
  }
  EXPECT_EQ(sink.count(PassId::Camera), 32u * 24u);
}

TEST(CameraPass, MissesLeaveEmptySamples) {
  Scene s;
  test::add_quad(s, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, test::material("m", 1.0f),
                 "small");
  test::Fixture fx(std::move(s), {});
  GBuffer g = fx.gbuffer(fx.frame());
  size_t hits = 0;
  for (const GSample& gs : g.samples) hits += gs.surface.hit();
  EXPECT_GT(hits, 0u);
  EXPECT_LT(hits, g.samples.size());
}

TEST(GBuffer, HalfResolutionPicksOneSamplePerQuadRotatingWithTheFrame) {
  GBuffer g;
  g.width = 6;
  g.height = 4;
  for (uint32_t p = 0; p < 24; ++p) {
    GSample s;
    s.pixel = p;
    g.samples.push_back(s);
  }
  EXPECT_EQ(GBuffer::cell_count(6, 4, 0.5f), 6u);
  EXPECT_EQ(GBuffer::cell_count(1920, 1080, 0.5f), 1920u * 1080u / 4u);
  EXPECT_EQ(GBuffer::cell_count(5, 3, 0.5f), 6u);  // partial cells at the edges count
  for (uint32_t frame = 0; frame < 4; ++frame) {
    std::vector<uint32_t> chosen = g.select(0.5f, frame);
    ASSERT_EQ(chosen.size(), 6u);
    // Cell 0 holds pixels 0, 1, 6, 7 in that order.
    const uint32_t quad[4] = {0, 1, 6, 7};
    EXPECT_EQ(chosen[0], quad[frame]);
    for (uint32_t c = 0; c < 6; ++c)
      EXPECT_EQ(GBuffer::cell_of(g.samples[chosen[c]].pixel, 6, 4, 0.5f), c);
  }
  EXPECT_EQ(g.select(1.0f, 0).size(), 24u);
}

}  // namespace
}  // namespace rtsim::pipeline
