// What a spec leaves to its scene: the file's first camera and its lights, a sun (and a line
// saying so) when nothing lights the scene, and a camera inside closed geometry that sees walls.
#include "workloads/pipeline/scene_defaults.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "traces/embree_scene.h"
#include "traces/error.h"
#include "workloads/pipeline/pipeline.h"
#include "workloads/pipeline/workload.h"

namespace rtsim::pipeline {
namespace {

bool mentions(const std::vector<std::string>& notes, const std::string& text) {
  for (const std::string& n : notes)
    if (n.find(text) != std::string::npos) return true;
  return false;
}

TEST(SceneDefaults, AnAutomaticCameraTakesTheFilesFirstCameraWhole) {
  Scene scene = load_scene("grid:64");
  scene.source = "level.gltf";
  scene.cameras.push_back({"eye", {1, 2, 5}, {-1, 0, 0}, {0, 0, 1}, 45.0f});
  scene.cameras.push_back({"other", {9, 9, 9}, {0, 0, -1}, {0, 1, 0}, 30.0f});
  WorkloadSpec spec = default_spec_for_scene("grid:64");
  std::vector<std::string> notes = adopt_scene_defaults(spec, scene);
  EXPECT_EQ(*spec.camera.position, glm::vec3(1, 2, 5));
  EXPECT_EQ(*spec.camera.look_at, glm::vec3(0, 2, 5));
  EXPECT_EQ(spec.camera.up, glm::vec3(0, 0, 1));
  EXPECT_EQ(spec.camera.fov, 45.0f);
  EXPECT_TRUE(mentions(notes, "camera 0 'eye' of level.gltf: at (1, 2, 5)")) << notes.front();

  WorkloadSpec placed = default_spec_for_scene("grid:64");
  placed.camera.position = glm::vec3(3, 3, 3);
  adopt_scene_defaults(placed, scene);
  EXPECT_EQ(*placed.camera.position, glm::vec3(3, 3, 3)) << "the spec's own camera wins";
  EXPECT_FALSE(placed.camera.look_at.has_value()) << "its look-at point stays automatic";
}

// A scene with a perspective camera behind an orthographic one (Debian's assimp-testmodels
// glTF2/cameras/Cameras.gltf has the two, the other way round).
Scene two_cameras() {
  Scene scene = load_scene("grid:64");
  scene.source = "level.gltf";
  SceneCamera top{"top", {0, 9, 0}, {0, -1, 0}, {0, 0, -1}, 60.0f, true, 4.0f, 3.0f};
  scene.cameras.push_back(top);
  scene.cameras.push_back({"eye", {1, 2, 5}, {-1, 0, 0}, {0, 1, 0}, 45.0f});
  return scene;
}

TEST(SceneDefaults, AnOrthographicCameraIsPassedOverWithALine) {
  WorkloadSpec spec = default_spec_for_scene("grid:64");
  std::vector<std::string> notes = adopt_scene_defaults(spec, two_cameras());
  EXPECT_EQ(*spec.camera.position, glm::vec3(1, 2, 5)) << "the first perspective camera";
  EXPECT_EQ(spec.camera.fov, 45.0f);
  EXPECT_TRUE(mentions(notes, "camera 0 'top' of level.gltf is orthographic: not adopted"));
  EXPECT_TRUE(mentions(notes, "camera 1 'eye' of level.gltf: at (1, 2, 5)"));
}

TEST(SceneDefaults, CameraIndexPicksACameraAndFovOverridesItsAngle) {
  WorkloadSpec spec = read_spec(std::string(RTSIM_SOURCE_DIR) + "/workloads/specs/grid.toml");
  spec.camera.position = glm::vec3(7, 7, 7);
  apply_overrides(spec, make_overrides({"", 0, std::nullopt, "", "", "", "", 1u, 20.0}));
  std::vector<std::string> notes = adopt_scene_defaults(spec, two_cameras());
  EXPECT_EQ(*spec.camera.position, glm::vec3(1, 2, 5)) << "the spec's camera gives way";
  EXPECT_EQ(*spec.camera.look_at, glm::vec3(0, 2, 5));
  EXPECT_EQ(spec.camera.fov, 20.0f) << "--fov, not the file camera's 45";
  EXPECT_TRUE(mentions(notes,
                       "camera 1 'eye' of level.gltf: at (1, 2, 5) looking along (-1, 0, "
                       "0), 20 degrees high (--fov)"));
}

TEST(SceneDefaults, ACameraIndexTheSceneCannotTakeNamesTheSceneAndTheCameras) {
  auto refusal = [](uint32_t index) {
    WorkloadSpec spec = default_spec_for_scene("grid:64");
    apply_overrides(spec, make_overrides({"", 0, std::nullopt, "", "", "", "", index}));
    try {
      adopt_scene_defaults(spec, two_cameras());
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal(2),
            "level.gltf: --camera-index 2: the scene has 2 cameras (0 to 1; rtsim scene-info lists "
            "them)");
  EXPECT_EQ(refusal(0),
            "level.gltf: --camera-index 0: camera 'top' is orthographic; rtsim's camera is a "
            "pinhole (perspective): choose a perspective camera or give --camera and --look-at");
  WorkloadSpec spec = default_spec_for_scene("grid:64");
  apply_overrides(spec, make_overrides({"", 0, std::nullopt, "", "", "", "", 0u}));
  EXPECT_THROW(adopt_scene_defaults(spec, load_scene("grid:64")), InputError) << "no cameras";
}

TEST(SceneDefaults, ASpecWithoutLightsTakesTheFilesLights) {
  Scene scene = load_scene("grid:64");
  SceneLight spot;
  spot.type = SceneLight::Type::Spot;
  spot.position = {0, 4, 0};
  spot.direction = {0, -1, 0};
  spot.color = {5, 5, 5};
  spot.outer_cone_degrees = 20;
  scene.lights.push_back(spot);
  WorkloadSpec spec = default_spec_for_scene("grid:64");
  std::vector<std::string> notes = adopt_scene_defaults(spec, scene);
  ASSERT_EQ(spec.lights.size(), 1u) << "no sun besides the file's light";
  EXPECT_EQ(spec.lights[0].type, LightType::Spot);
  EXPECT_EQ(*spec.lights[0].position, glm::vec3(0, 4, 0));
  EXPECT_EQ(spec.lights[0].color, glm::vec3(5, 5, 5));
  EXPECT_EQ(spec.lights[0].cone_angle, 20.0f);
  EXPECT_TRUE(mentions(notes, "1 light(s) of"));

  WorkloadSpec lit = default_spec_for_scene("grid:64");
  lit.lights.push_back(LightSpec{});
  adopt_scene_defaults(lit, scene);
  EXPECT_EQ(lit.lights.size(), 1u) << "the spec's lights win";
}

TEST(SceneDefaults, NothingLitGetsADirectionalSunAndSaysWhich) {
  WorkloadSpec spec = default_spec_for_scene("grid:64");
  std::vector<std::string> notes = adopt_scene_defaults(spec, load_scene("grid:64"));
  ASSERT_EQ(spec.lights.size(), 1u);
  EXPECT_EQ(spec.lights[0].type, LightType::Directional);
  EXPECT_LT(spec.lights[0].direction.y, -0.8f) << "from above, against the spec's up";
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("no light in the spec or in builtin:grid"), std::string::npos)
      << notes[0];
  EXPECT_NE(notes[0].find("added a directional sun pointing ("), std::string::npos);

  WorkloadSpec cornell = default_spec_for_scene("cornell");
  EXPECT_TRUE(adopt_scene_defaults(cornell, load_scene("cornell")).empty())
      << "the emissive ceiling lights it";
  EXPECT_TRUE(cornell.lights.empty());
}

TEST(SceneDefaults, ACameraInsideClosedGeometrySeesItsWallsAndShootsShadowRays) {
  std::string path = (std::filesystem::temp_directory_path() /
                      ("rtsim-closed-box-" + std::to_string(::getpid()) + ".obj"))
                         .string();
  {
    std::ofstream obj(path);
    for (int i = 0; i < 8; ++i)
      obj << "v " << (i & 1 ? 2 : -2) << ' ' << (i & 2 ? 2 : -2) << ' ' << (i & 4 ? 2 : -2) << '\n';
    for (const char* face : {"1 3 4 2", "5 6 8 7", "1 2 6 5", "3 7 8 4", "1 5 7 3", "2 4 8 6"})
      obj << "f " << face << '\n';
  }
  WorkloadSpec spec = default_spec_for_scene(path);
  spec.width = 32;
  spec.height = 24;
  spec.camera.position = glm::vec3(0.5f, 0.0f, 0.0f);
  spec.camera.look_at = glm::vec3(2.0f, 0.3f, 0.2f);
  Scene scene = load_scene(path);
  std::filesystem::remove(path);
  adopt_scene_defaults(spec, scene);
  EmbreeScene embree(scene.mesh, 1);
  Pipeline pipeline(spec, scene, embree);
  RaySink sink(nullptr, spec.width, spec.height, false);
  FrameResults frame;
  pipeline.run_frame(0, sink, frame);
  for (const GSample& s : frame.gbuffer.samples) ASSERT_GT(s.depth, 0.0f) << "a wall in view";
  EXPECT_GT(pipeline.summary().passes[size_t(PassId::Shadow)].rays, 0u)
      << "shadow rays toward the added sun from the surfaces that face it";
}

}  // namespace
}  // namespace rtsim::pipeline
