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
  EXPECT_EQ(r.err, "rtsim: error: RTSIM_MAX_MEMORY: expected a number of bytes, got 'lots'\n");
}

}  // namespace
}  // namespace rtsim::test
