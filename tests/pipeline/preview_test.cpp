// The preview and density pictures: the Cornell box comes out with a red wall on the left, a
// green one on the right, a lit floor and black outside the box; density images exist for the
// passes that shot rays and only for those.
#include "workloads/pipeline/preview.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "workloads/pipeline/trace.h"

namespace rtsim::pipeline {
namespace {

std::string spec_path(const std::string& name) {
  return std::string(RTSIM_SOURCE_DIR) + "/workloads/specs/" + name + ".toml";
}

TEST(Preview, CornellBoxLooksLikeTheCornellBox) {
  WorkloadSpec spec = read_spec(spec_path("cornell"));
  spec.width = 160;
  spec.height = 90;
  spec.passes.gi.budget = 20000;
  Scene scene = load_scene(spec.scene);
  EmbreeScene embree(scene.mesh, 1);
  Pipeline p(spec, scene, embree);
  RaySink sink(nullptr, spec.width, spec.height, false);
  FrameResults frame;
  p.run_frame(0, sink, frame);
  std::vector<uint8_t> rgb = tone_map(shade_frame(p, frame));
  ASSERT_EQ(rgb.size(), 160u * 90u * 3u);
  auto at = [&](float fx, float fy, int c) {
    auto x = uint32_t(fx * 160), y = uint32_t(fy * 90);
    return int(rgb[(y * 160 + x) * 3 + uint32_t(c)]);
  };
  EXPECT_GT(at(0.27f, 0.5f, 0), 2 * at(0.27f, 0.5f, 1)) << "red wall on the left";
  EXPECT_GT(at(0.73f, 0.5f, 1), at(0.73f, 0.5f, 0)) << "green wall on the right";
  EXPECT_GT(at(0.5f, 0.93f, 0) + at(0.5f, 0.93f, 1) + at(0.5f, 0.93f, 2), 150) << "lit floor";
  EXPECT_EQ(at(0.03f, 0.5f, 0) + at(0.03f, 0.5f, 1) + at(0.03f, 0.5f, 2), 0) << "no sky";
}

TEST(Preview, TraceWritesTheStreamThePreviewAndOneDensityImagePerActivePass) {
  WorkloadSpec spec = read_spec(spec_path("cornell"));
  spec.width = 64;
  spec.height = 36;
  spec.passes.gi.budget = 2000;
  std::string dir = ::testing::TempDir();
  TraceOptions options;
  options.output = dir + "preview-test.rays";
  options.preview = dir + "preview-test.png";
  TraceResult r = trace_workload(spec, options);
  std::vector<std::string> expected = {options.preview};
  for (const char* pass : {"camera", "shadow", "diffuse_gi", "gi_light", "ao", "all"})
    expected.push_back(density_image_path(options.preview, pass));
  EXPECT_EQ(r.images, expected);  // nothing for reflection, refraction, translucency
  for (const std::string& path : r.images) {
    EXPECT_TRUE(std::filesystem::exists(path)) << path;
    std::remove(path.c_str());
  }
  EXPECT_TRUE(std::filesystem::exists(options.output));
  std::remove(options.output.c_str());
  EXPECT_EQ(density_image_path("out/a.b/pic.png", "ao"), "out/a.b/pic.density-ao.png");
  EXPECT_EQ(density_image_path("out/a.b/pic", "ao"), "out/a.b/pic.density-ao.png");
}

}  // namespace
}  // namespace rtsim::pipeline
