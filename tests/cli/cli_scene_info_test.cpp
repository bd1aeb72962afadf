// rtsim scene-info on built-in scenes, real scene files and bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "run_rtsim.h"

namespace rtsim::test {
namespace {

TEST(CliSceneInfo, BuiltinGridHasExactlyTheRequestedTriangles) {
  RunResult r = run_rtsim("scene-info grid:12345");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("triangles    12345\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("scene        builtin:grid:12345\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("fingerprint  "), std::string::npos);
  EXPECT_NE(r.out.find("instances    none (one flat mesh)\n"), std::string::npos) << r.out;
}

// The forest is instanced: its BVH is two levels over the unique meshes, far smaller than one
// level over the flattened triangles.
TEST(CliSceneInfo, ForestReportsInstancesAndBothBvhs) {
  RunResult r = run_rtsim("scene-info forest:300000 --bvh");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("of 5 unique meshes: 32516 unique triangles"), std::string::npos) << r.out;
  auto bytes = [](const std::string& out) {
    size_t at = out.find("): ", out.find("bvh "));
    return at == std::string::npos ? 0.0 : std::stod(out.substr(at + 3));
  };
  EXPECT_NE(r.out.find("bvh          two levels, bvh8"), std::string::npos) << r.out;
  RunResult flat = run_rtsim("scene-info forest:300000 --bvh --set bvh.instancing=\"flatten\"");
  ASSERT_EQ(flat.exit_code, 0) << flat.err;
  EXPECT_NE(flat.out.find("bvh          one level, bvh8"), std::string::npos) << flat.out;
  EXPECT_GT(bytes(flat.out), 5 * bytes(r.out)) << r.out << flat.out;
  EXPECT_EQ(run_rtsim("scene-info forest:10 --bvh --set bvh.instancing=\"sideways\"").exit_code, 2);
}

TEST(CliSceneInfo, SameSceneSameFingerprint) {
  EXPECT_EQ(run_rtsim("scene-info cornell").out, run_rtsim("scene-info builtin:cornell").out);
  EXPECT_NE(run_rtsim("scene-info foliage:100").out, run_rtsim("scene-info foliage:101").out);
}

TEST(CliSceneInfo, SharedCornellBoxLoads) {
  std::string path = std::string(RTSIM_SHARED_SCENES) + "/cornell-box/CornellBox-Original.obj";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "../shared/scenes is absent: " << path;
  RunResult r = run_rtsim("scene-info " + path);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("triangles    36\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("instances    8 of 8 unique meshes: 36 unique triangles, 36 instanced\n"),
            std::string::npos)
      << "each OBJ group is a mesh placed once: " << r.out;
}

TEST(CliSceneInfo, MissingFileIsOneLineAndExit2) {
  RunResult r = run_rtsim("scene-info /nonexistent/scene.obj");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("/nonexistent/scene.obj"), std::string::npos) << r.err;
}

TEST(CliSceneInfo, ZeroTrianglesIsOneLineAndExit2) {
  std::string path = "/tmp/rtsim-cli-empty-" + std::to_string(getpid()) + ".obj";
  std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  RunResult r = run_rtsim("scene-info " + path);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
  std::remove(path.c_str());
}

TEST(CliSceneInfo, NanVertexIsOneLineAndExit2) {
  std::string path = "/tmp/rtsim-cli-nan-" + std::to_string(getpid()) + ".obj";
  std::ofstream(path) << "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n";
  RunResult r = run_rtsim("scene-info " + path);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
  std::remove(path.c_str());
}

TEST(CliSceneInfo, UnsupportedFormatIsOneLineAndExit2) {
  std::string path = "/tmp/rtsim-cli-" + std::to_string(getpid()) + ".xyz";
  std::ofstream(path) << "hello\n";
  RunResult r = run_rtsim("scene-info " + path);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
  std::remove(path.c_str());
}

// Broken OBJ and glTF files name their line, not assimp's words (scene_errors_test has the rest).
TEST(CliSceneInfo, BrokenObjAndGltfNameTheirLine) {
  std::string base = "/tmp/rtsim-cli-broken-" + std::to_string(getpid());
  std::ofstream(base + ".obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 5\n";
  std::ofstream(base + ".gltf") << "{\n  \"asset\": {\"version\": \"2.0\"},\n  \"meshes\": [\n";
  RunResult r = run_rtsim("scene-info " + base + ".obj");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(first_line(r.err), "rtsim: error: " + base +
                                   ".obj: line 5: '5' refers to vertex 5, but only 4 vertices "
                                   "('v' lines) are defined above this line");
  r = run_rtsim("scene-info " + base + ".gltf");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(first_line(r.err).rfind("rtsim: error: " + base + ".gltf: line 4: not valid JSON: ", 0),
            0u)
      << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  std::remove((base + ".obj").c_str());
  std::remove((base + ".gltf").c_str());
}

// A glTF 2.0 triangle (its buffer a data: URI) under a named node and material, a perspective
// camera looking at it, an orthographic one above, and a directional light.
std::string write_view_gltf(const std::string& path) {
  std::ofstream(path) << R"({
  "asset": {"version": "2.0"},
  "extensionsUsed": ["KHR_lights_punctual"],
  "extensions": {"KHR_lights_punctual": {"lights": [
    {"name": "sun", "type": "directional", "color": [1, 0.5, 0.5], "intensity": 3}]}},
  "scene": 0,
  "scenes": [{"nodes": [0, 1, 2, 3]}],
  "nodes": [
    {"name": "tri_node", "mesh": 0},
    {"name": "eye", "camera": 0, "translation": [0.3, 0.3, 3]},
    {"name": "top", "camera": 1, "translation": [0, 9, 0]},
    {"name": "sun_node", "extensions": {"KHR_lights_punctual": {"light": 0}}}
  ],
  "cameras": [
    {"type": "perspective", "perspective": {"yfov": 0.8, "aspectRatio": 1, "znear": 0.1}},
    {"type": "orthographic", "orthographic": {"xmag": 4, "ymag": 2, "znear": 0.1, "zfar": 99}}],
  "materials": [{"name": "paint", "pbrMetallicRoughness": {
    "baseColorFactor": [0.9, 0.1, 0.1, 1], "metallicFactor": 1, "roughnessFactor": 0.2}}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
  "buffers": [{"byteLength": 42, "uri":
    "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIA"}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                  {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
     "min": [0, 0, 0], "max": [1, 1, 0]},
    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]
})";
  return path;
}

// What [[material]] rules match, and what a spec could adopt: object and material names,
// cameras (the orthographic one as such), lights with direction and intensity.
TEST(CliSceneInfo, AGltfListsObjectsMaterialsCamerasAndLights) {
  std::string file = write_view_gltf(::testing::TempDir() + "cli-scene-info-view.gltf");
  RunResult r = run_rtsim("scene-info " + file);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* line :
       {"objects      1\n  names      'tri_node'\n",
        "materials    2\n  0          'paint': base colour [0.9, 0.1, 0.1], roughness 0.2, "
        "metalness 1\n  1          '': ",  // assimp adds a default material
        "cameras      2 (trace, run: --camera-index N)\n  0          'eye' perspective at [0.3, "
        "0.3, 3] looking [0, 0, -1], up [0, 1, 0], 45.8 degrees high\n",
        "  1          'top' orthographic at [0, 9, 0] looking [0, 0, -1], up [0, 1, 0]: a view box "
        "8 x 4 wide and high (not adopted: rtsim's camera is a pinhole)\n",
        "lights       1\n  0          ",
        " directional, direction [0, 0, -1], intensity 3 lux, colour [1, 0.5, 0.5]\n"})
    EXPECT_NE(r.out.find(line), std::string::npos) << line << "\nin:\n" << r.out;
  EXPECT_EQ(r.out.find("60 degrees"), std::string::npos) << r.out;
}

// --camera-index picks a file camera and --fov its angle; a camera the scene cannot give, or an
// orthographic one, is one line and exit 2 before anything is written.
TEST(CliSceneInfo, TraceTakesTheCameraIndexAndFovItIsGiven) {
  std::string file = write_view_gltf(::testing::TempDir() + "cli-camera-index.gltf");
  std::string out = ::testing::TempDir() + "cli-camera-index.rays";
  RunResult r =
      run_rtsim("trace " + file + " --camera-index 0 --fov 30 --resolution 16x16 -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("trace: camera 0 'eye' of " + file +
                       ": at (0.3, 0.3, 3) looking along (0, 0, -1), 30 degrees high (--fov)\n"),
            std::string::npos)
      << r.err;
  for (const std::string& bad :
       {std::string("--camera-index 1"), std::string("--camera-index 7"), std::string("--fov 0"),
        std::string("--camera-index 0 --camera 1,1,1")}) {
    std::remove(out.c_str());
    RunResult refused = run_rtsim("trace " + file + " " + bad + " --resolution 16x16 -o " + out);
    EXPECT_EQ(refused.exit_code, 2) << bad << ": " << refused.err;
    EXPECT_EQ(count_lines(refused.err), 1) << bad << ": " << refused.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << bad;
  }
  RunResult ortho = run_rtsim("trace " + file + " --camera-index 1 -o " + out);
  EXPECT_NE(ortho.err.find(file + ": --camera-index 1: camera 'top' is orthographic"),
            std::string::npos)
      << ortho.err;
  RunResult beyond = run_rtsim("trace " + file + " --camera-index 7 -o " + out);
  EXPECT_NE(beyond.err.find(file + ": --camera-index 7: the scene has 2 cameras (0 to 1"),
            std::string::npos)
      << beyond.err;
}

TEST(CliSceneInfo, AGltf1FileIsOneLineNamingItsVersionAndExit2) {
  std::string file = ::testing::TempDir() + "cli-gltf1.gltf";
  std::ofstream(file) << R"({"asset": {"version": "1.0"}, "meshes": {"box": {"primitives": []}}})";
  RunResult r = run_rtsim("scene-info " + file);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "rtsim: error: " + file +
                       ": asset.version: '1.0': glTF 1.0; rtsim reads glTF 2.0 (re-export the file "
                       "as glTF 2.0)\n");
}

// Runs rtsim with RTSIM_MAX_MEMORY set (what memory planning plans against).
RunResult run_with_memory(const std::string& bytes, const std::string& args) {
  setenv("RTSIM_MAX_MEMORY", bytes.c_str(), 1);
  RunResult r = run_rtsim(args);
  unsetenv("RTSIM_MAX_MEMORY");
  return r;
}

TEST(CliMemoryPlan, ASceneBeyondTheMemoryIsRefusedWithTheEstimate) {
  RunResult r = run_with_memory("100000000", "scene-info grid:10000000");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err,
            "rtsim: error: builtin:grid:10000000: a scene of 10000000 triangles needs about 0.3 GB "
            "of memory, more than the 0.1 GB available; ask for fewer triangles\n");
  EXPECT_EQ(run_with_memory("100000000", "scene-info grid:1000000").exit_code, 0) << "28 MB fits";
}

TEST(CliMemoryPlan, ATraceBeyondTheMemoryIsRefusedBeforeItStarts) {
  RunResult r = run_with_memory("500000000", "trace cornell --resolution 4096x4096 -o /dev/null");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("rtsim: error: cornell: tracing 4096 x 4096 pixels of a ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("needs about 1.7 GB of memory, more than the 0.5 GB available; lower the "
                       "resolution"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(count_lines(r.err), 1);
}

TEST(CliMemoryPlan, ABvhBuildBeyondTheMemoryIsRefusedAndALargeOneSaysEachStep) {
  std::string stream = ::testing::TempDir() + "cli-memory-grid.rays";
  ASSERT_EQ(run_rtsim("trace grid:1000000 -q --resolution 16x9 -o " + stream).exit_code, 0);
  RunResult refused = run_with_memory("100000000", "sim " + stream + " --no-verify -q -o " +
                                                       ::testing::TempDir() + "cli-memory-no");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(refused.err,
            "rtsim: error: bvh: building a BVH over 1000000 triangles needs about 0.2 GB of "
            "memory, more than the 0.1 GB available; use a smaller scene\n");
  RunResult built = run_rtsim("sim " + stream + " --no-verify -o " + ::testing::TempDir() +
                              "cli-memory-grid-sim");
  ASSERT_EQ(built.exit_code, 0) << built.err;
  for (const char* step :
       {"bvh:   binned SAH build in ", "bvh:   collapse in ", "bvh:   treelets and node order in ",
        "bvh:   encode in ", " B a triangle), built in "})
    EXPECT_NE(built.err.find(step), std::string::npos) << step << " in:\n" << built.err;
  std::remove(stream.c_str());
}

TEST(CliMemoryPlan, FlatteningAForestBeyondTheMemoryIsRefusedWithTheEstimate) {
  const std::string forest = "scene-info forest:100000000 --bvh";
  RunResult r = run_with_memory("1000000000", forest + " --set bvh.instancing=\"flatten\"");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(
      r.err,
      "rtsim: error: builtin:forest:100000000: flattening 100005416 instanced triangles needs "
      "about 5.6 GB of memory, more than the 1.0 GB available; keep its instances "
      "(bvh.instancing = \"auto\" or \"two_level\", no --flatten)\n");
  EXPECT_EQ(run_with_memory("1000000000", forest).exit_code, 0) << "its instances fit";
}

TEST(CliMemoryPlan, ABadLimitIsOneLine) {
  RunResult r = run_with_memory("lots", "scene-info grid:1000");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err,
            "rtsim: error: RTSIM_MAX_MEMORY: 'lots' is not a size (bytes, or a number "
            "with K, M, G or T (KiB, MiB, GiB, TiB): 64K, 4M)\n");
  r = run_with_memory("1G", "scene-info grid:1000");
  EXPECT_EQ(r.exit_code, 0) << "a size with a suffix: " << r.err;
  r = run_with_memory("1K", "scene-info grid:1000000");
  EXPECT_EQ(r.exit_code, 2) << "1K is 1,024 bytes: " << r.err;
}

}  // namespace
}  // namespace rtsim::test
