// Robust secondary origins on every sample workload: no secondary ray (shadow, reflection,
// reflected shadow, GI, light connection, AO, refraction, translucency) may hit the triangle
// it leaves from. Embree traces each ray as written; scenes from ../shared/scenes are skipped
// with a message where that folder is absent.
#include <gtest/gtest.h>

#include <filesystem>

#include "traces/embree_scene.h"
#include "workloads/pipeline/pipeline.h"
#include "workloads/scene.h"

namespace rtsim::pipeline {
namespace {

class RobustOffsets : public ::testing::TestWithParam<const char*> {};

TEST_P(RobustOffsets, NoSecondaryRayHitsItsOwnTriangle) {
  std::string path = std::string(RTSIM_SOURCE_DIR) + "/workloads/specs/" + GetParam() + ".toml";
  WorkloadSpec spec = read_spec(path);
  if (!is_builtin_scene(spec.scene) && !std::filesystem::exists(spec.scene))
    GTEST_SKIP() << spec.scene << " is absent (../shared/scenes is not on this machine)";
  spec.width = 80;
  spec.height = 45;
  spec.frames = std::min(spec.frames, 2u);
  spec.passes.gi.budget = 3000;
  Scene scene = load_scene(spec.scene);
  EmbreeScene embree(scene.mesh, 1);
  Pipeline pipeline(spec, scene, embree);
  RaySink sink(nullptr, spec.width, spec.height, false);
  uint64_t secondary = 0, self_hits = 0, bad = 0;
  sink.observer = [&](const Ray& ray, PassId pass, uint32_t origin) {
    bad += !ray_problem(ray).empty();
    if (pass == PassId::Camera) return;
    ASSERT_NE(origin, kNoHit) << pass_name(pass);
    ++secondary;
    Hit hit = embree.intersect(ray);
    if (hit.prim == origin) {
      ++self_hits;
      ADD_FAILURE() << pass_name(pass) << " ray re-hits its own triangle " << origin
                    << " at t = " << hit.t;
    }
  };
  FrameResults frame;
  for (uint32_t f = 0; f < pipeline.frames_to_run(); ++f) pipeline.run_frame(f, sink, frame);
  EXPECT_GT(secondary, 1000u);
  EXPECT_EQ(self_hits, 0u) << "of " << secondary << " secondary rays";
  EXPECT_EQ(bad, 0u);
}

INSTANTIATE_TEST_SUITE_P(SampleWorkloads, RobustOffsets,
                         ::testing::Values("cornell", "pica", "grid", "foliage", "pica-orbit",
                                           "sponza", "sibenik", "conference", "bunny", "dragon",
                                           "cornell-box"),
                         [](const auto& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace rtsim::pipeline
