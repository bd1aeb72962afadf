// Translucency pass: pushed-in origins and inner-hemisphere directions.
#include "workloads/pipeline/pass_translucency.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "tests/pipeline/test_scenes.h"

namespace rtsim::pipeline {
namespace {

using test::RecordedRays;
using test::recording_sink;

TEST(TranslucencyPass, InnerHemisphereFromAPushedInOrigin) {
  Scene s;
  Material jade = test::material("jade", 0.5f);
  jade.translucency = 0.5f;
  test::add_wall(s, jade);
  test::Fixture fx(std::move(s), {});
  FrameContext f = fx.frame();
  GBuffer g = fx.gbuffer(f);
  RecordedRays rays;
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
