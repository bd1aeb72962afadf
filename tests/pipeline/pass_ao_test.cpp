// AO pass: short any-hit rays from camera hits at half resolution.
#include "workloads/pipeline/pass_ao.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "tests/pipeline/test_scenes.h"

namespace rtsim::pipeline {
namespace {

using test::RecordedRays;
using test::recording_sink;

TEST(AoPass, ShortAnyHitRaysAtHalfResolution) {
  Scene s;
  test::add_wall(s, test::material("wall", 1.0f));
  test::Fixture fx(std::move(s), {});
  fx.spec.passes.ao.radius = 0.5f;
  FrameContext f = fx.frame();
  GBuffer g = fx.gbuffer(f);
  RecordedRays rays;
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

}  // namespace
}  // namespace rtsim::pipeline
