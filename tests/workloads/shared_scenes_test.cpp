// The real research scenes in ../shared/scenes load with the triangle counts and bounds that
// `assimp info FILE` prints (its "Faces:" line, which counts the zero-area triangles it turns
// into lines; rtsim keeps them as triangles). Skipped where the folder is absent.
#include <gtest/gtest.h>

#include <filesystem>

#include "workloads/scene.h"

namespace rtsim {
namespace {

struct SharedScene {
  const char* path;  // relative to RTSIM_SHARED_SCENES
  size_t triangles;
  glm::vec3 lo, hi;  // assimp info's "Minimum point" and "Maximum point"
};

const SharedScene kScenes[] = {
    {"cornell-box/CornellBox-Original.obj", 36, {-1.02f, 0.0f, -1.04f}, {1.0f, 1.99f, 0.99f}},
    {"bunny/bun_zipper.ply",
     69451,
     {-0.094690f, 0.032987f, -0.061874f},
     {0.061009f, 0.187321f, 0.058800f}},
    {"dragon-vcg-100k/dragon.ply",
     100000,
     {-1.352945f, -0.954207f, -0.605046f},
     {1.352945f, 0.954207f, 0.605046f}},
    {"sibenik/sibenik.obj", 75284, {-20.1411f, -15.3123f, -8.4968f}, {20.1411f, 15.3f, 8.4968f}},
    {"sponza-dabrovic/sponza.obj",
     66454,
     {-17.402760f, -0.906689f, -7.798512f},
     {17.417240f, 15.653312f, 7.801489f}},
    {"conference/conference.obj",
     331179,
     {-1020.130005f, -2.7924f, -1055.660034f},
     {1685.810059f, 650.293030f, 668.489014f}},
};

std::string shared_path(const char* relative) {
  return std::string(RTSIM_SHARED_SCENES) + "/" + relative;
}

#define SKIP_WITHOUT_SHARED_SCENES()                               \
  if (!std::filesystem::is_directory(RTSIM_SHARED_SCENES))         \
  GTEST_SKIP() << "no shared scene folder at " RTSIM_SHARED_SCENES \
                  " (only on the project's machines)"

void expect_near(const glm::vec3& a, const glm::vec3& b, const std::string& what) {
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(a[k], b[k], 1e-5f * std::max(1.0f, std::abs(b[k]))) << what << " axis " << k;
}

TEST(SharedScenes, LoadWithAssimpInfoCounts) {
  SKIP_WITHOUT_SHARED_SCENES();
  for (const SharedScene& expected : kScenes) {
    Scene s = load_scene(shared_path(expected.path));
    EXPECT_EQ(s.triangle_count(), expected.triangles) << expected.path;
    expect_near(s.bounds.lo, expected.lo, std::string(expected.path) + " bounds.lo");
    expect_near(s.bounds.hi, expected.hi, std::string(expected.path) + " bounds.hi");
    EXPECT_EQ(load_scene(shared_path(expected.path)).fingerprint, s.fingerprint) << expected.path;
  }
}

TEST(SharedScenes, CornellBoxObjectsAndLight) {
  SKIP_WITHOUT_SHARED_SCENES();
  Scene s = load_scene(shared_path("cornell-box/CornellBox-Original.obj"));
  EXPECT_EQ(s.object_names, (std::vector<std::string>{"floor", "ceiling", "backWall", "rightWall",
                                                      "leftWall", "shortBox", "tallBox", "light"}));
  size_t emissive = 0;
  for (size_t t = 0; t < s.triangle_count(); ++t) {
    const Material& m = s.materials[s.material_ids[t]];
    if (m.emission.x > 0.0f) {
      ++emissive;
      EXPECT_EQ(m.name, "light");
      EXPECT_EQ(m.emission, glm::vec3(17.0f, 12.0f, 4.0f));
    }
  }
  EXPECT_EQ(emissive, 2u);
}

// The arbiter classifies degenerate triangles, so the loader must not drop them: the
// conference room has 52,670 triangles with coincident corners (its SOURCE.txt).
TEST(SharedScenes, ConferenceKeepsZeroAreaTriangles) {
  SKIP_WITHOUT_SHARED_SCENES();
  Scene s = load_scene(shared_path("conference/conference.obj"));
  size_t degenerate = 0;
  for (size_t t = 0; t < s.triangle_count(); ++t) {
    glm::vec3 a = s.mesh.vertex(t, 0), b = s.mesh.vertex(t, 1), c = s.mesh.vertex(t, 2);
    degenerate += a == b || b == c || a == c;
  }
  EXPECT_EQ(degenerate, 52670u);
}

TEST(SharedScenes, SponzaGroupsBecomeObjects) {
  SKIP_WITHOUT_SHARED_SCENES();
  Scene s = load_scene(shared_path("sponza-dabrovic/sponza.obj"));
  EXPECT_EQ(s.object_names.size(), 34u);
  EXPECT_EQ(s.object_names.front(), "arcs_floor_small");
  EXPECT_EQ(s.materials.size(), 1u);
}

}  // namespace
}  // namespace rtsim
