// Golden test on the shared research scenes: diffuse and camera rays, model against Embree,
// every node format and width (Intel's xe6 too), nothing unexplained. Skips where ../shared is
// absent.
#include <gtest/gtest.h>

#include <filesystem>

#include "model/verify/verifier.h"
#include "model_test_util.h"
#include "workloads/scene.h"

namespace rtsim {
namespace {

void verify_scene(const std::string& relative, size_t rays) {
  std::string path = std::string(RTSIM_SHARED_SCENES) + "/" + relative;
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " absent (no ../shared here)";
  Scene scene = load_scene(path);
  EmbreeScene embree(scene.mesh);
  std::vector<Ray> all = sample_diffuse_rays(scene.mesh, rays, 7);
  for (const Ray& r : sample_camera_rays(scene.mesh, 64, 48)) all.push_back(r);
  std::vector<BvhConfig> configs = test::all_configs();
  configs.push_back(test::config(NodeFormat::Xe6, 6, 2));  // Intel Xe: quantised nodes, quads
  configs.back().triangle_format = TriangleFormat::XeQuad;
  for (const BvhConfig& c : configs) {
    BvhImage image = build_bvh_image(scene.mesh, c);
    TraversalUnit unit(image);
    Verifier verifier(scene.mesh, unit, embree);
    for (const Ray& r : all) verifier.check(r);
    EXPECT_EQ(verifier.report().unexplained(), 0u) << relative << " " << describe(c);
    EXPECT_GT(verifier.report().agree, all.size() * 99 / 100) << relative << " " << describe(c);
  }
}

TEST(SharedScenes, CornellBox) {
  verify_scene("cornell-box/CornellBox-Original.obj", 20000);
}
TEST(SharedScenes, Bunny) {
  verify_scene("bunny/bun_zipper.ply", 20000);
}
TEST(SharedScenes, Sibenik) {
  verify_scene("sibenik/sibenik.obj", 20000);
}

}  // namespace
}  // namespace rtsim
