// Hostile scenes and workloads (issue 63): cameras and lights beyond the range rtsim traces, glTF
// node trees that are deep, shared or cyclic, JSON nested past what assimp's parser recurses
// through, and outputs that would replace an input. Each ends with one line naming the file and
// the place, exit code 2, and nothing written.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/cli/run_rtsim.h"
#include "tests/temp_dir.h"

namespace rtsim {
namespace {

namespace fs = std::filesystem;

// One triangle in a data: URI, placed by `nodes` (a JSON array) under the root nodes `roots`.
std::string triangle_gltf(const std::string& nodes, const std::string& roots,
                          const std::string& extra = "") {
  return R"({"asset": {"version": "2.0"},
  "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,)"
         R"(AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                 "min": [0, 0, 0], "max": [1, 1, 0]}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "cameras": [{"type": "perspective", "perspective": {"yfov": 1.0, "znear": 0.1}}],)" +
         extra + R"("nodes": )" + nodes + R"(, "scenes": [{"nodes": )" + roots +
         R"(}], "scene": 0})";
}

// Nodes 0..n-1, node i listing node i+1 `times` times; the last one places the mesh.
std::string node_chain(int n, int times) {
  std::string nodes = "[";
  for (int i = 0; i + 1 < n; ++i) {
    nodes += "{\"children\": [";
    for (int t = 0; t < times; ++t) nodes += (t ? ", " : "") + std::to_string(i + 1);
    nodes += "]}, ";
  }
  return nodes + "{\"mesh\": 0}]";
}

class CliHostileScenes : public ::testing::Test {
 protected:
  // Runs rtsim and checks the one-line error: exit 2, "rtsim: error: " + expected at its start.
  void expect_error(const std::string& args, const std::string& expected) {
    test::RunResult r = test::run_rtsim(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("rtsim: error: " + expected, 0), 0u)
        << args << "\nexpected: " << expected << "\ngot: " << r.err;
  }
  // The names in the scratch folder: nothing written beside the inputs, no temporary left.
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_.path(".")))
      names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  test::TempDir dir_;
};

// The spec's keys and the other options: tests/pipeline/spec_test.cpp.
TEST_F(CliHostileScenes, ACameraBeyondTheTracedRangeIsRefusedBeforeAnythingIsWritten) {
  std::string out = dir_.path("x.rays");
  expect_error("trace cornell --camera 2e18,0,0 --look-at 0,0,0 -q -o " + out,
               "--camera 2e18,0,0: (2e+18, 0, 0) is beyond +-1e+15");
  std::string far_camera = triangle_gltf(
      R"([{"mesh": 0}, {"name": "far", "camera": 0, "translation": [0, 0, 4e18]}])", "[0, 1]");
  std::string gltf = dir_.write("far.gltf", far_camera);
  expect_error("trace " + gltf + " -q -o " + out,
               gltf + ": camera 'far': (0, 0, 4e+18) is beyond +-1e+15");
  // A narrow, tall view of a scene that fills the range: the fitted camera stands too far out.
  dir_.write("big.obj", "v -1e15 0 0\nv 1e15 0 0\nv 0 1e15 0\nf 1 2 3\n");
  std::string narrow = dir_.write(
      "narrow.toml", "scene = \"big.obj\"\nresolution = \"1x65536\"\n[camera]\nfov = 1\n");
  expect_error("trace " + narrow + " -q -o " + out,
               narrow + ": camera: the camera fit to the scene stands at (");
  EXPECT_EQ(files(), (std::vector<std::string>{"big.obj", "far.gltf", "narrow.toml"}))
      << "no stream and no temporary";
}

TEST_F(CliHostileScenes, ANodeChainTooDeepIsRefusedWithItsDepth) {
  std::string deep = dir_.write("deep.gltf", triangle_gltf(node_chain(20000, 1), "[0]"));
  for (const std::string& command :
       {std::string("scene-info "), "trace -q -o " + dir_.path("x.rays") + " "})
    expect_error(command + deep,
                 deep + ": node 1000: lies 1001 levels deep; rtsim reads node trees up to 1000");
  std::string fine = dir_.write("fine.gltf", triangle_gltf(node_chain(1000, 1), "[0]"));
  EXPECT_EQ(test::run_rtsim("scene-info " + fine).exit_code, 0) << "1000 levels are read";
}

TEST_F(CliHostileScenes, JsonNestedTooDeepIsRefusedWithItsLine) {
  std::string nested = std::string(100000, '[') + std::string(100000, ']');
  std::string gltf = dir_.write(
      "nested.gltf", triangle_gltf("[{\"mesh\": 0}]", "[0]", "\"extras\": " + nested + ",\n"));
  expect_error("scene-info " + gltf,
               gltf +
                   ": line 7: JSON nested deeper than 256 levels; rtsim reads glTF documents "
                   "up to that depth");
}

TEST_F(CliHostileScenes, ANodeGraphThatIsNotATreeNamesTheNodeAndItsParents) {
  // 40 nodes that each list the next twice: 2^40 paths to the last one, from 1 KB.
  std::string twice = dir_.write("twice.gltf", triangle_gltf(node_chain(40, 2), "[0]"));
  expect_error("scene-info " + twice,
               twice + ": node 0: lists child 1 twice; glTF node hierarchies are trees");
  std::string diamond = dir_.write(
      "diamond.gltf",
      triangle_gltf(R"([{"children": [1, 2]}, {"children": [3]}, {"children": [3]}, {"mesh": 0}])",
                    "[0]"));
  expect_error("scene-info " + diamond,
               diamond +
                   ": node 3: has two parents, nodes 1 and 2; glTF node hierarchies are "
                   "trees");
  std::string cycle = dir_.write(
      "cycle.gltf", triangle_gltf(R"([{"mesh": 0}, {"children": [2]}, {"children": [1]}])", "[0]"));
  expect_error("scene-info " + cycle, cycle + ": node 1: is its own ancestor");
  std::string child_root =
      dir_.write("child-root.gltf", triangle_gltf(R"([{"children": [1]}, {"mesh": 0}])", "[0, 1]"));
  expect_error("scene-info " + child_root,
               child_root + ": scenes[0]: lists node 1, a child of node 0, as a root node");
  std::string missing =
      dir_.write("missing.gltf", triangle_gltf(R"([{"children": [7], "mesh": 0}])", "[0]"));
  expect_error("scene-info " + missing,
               missing + ": node 0: child 7 does not exist (the file has 1 nodes)");
}

TEST_F(CliHostileScenes, BillionsOfZeroFilledGpuInstancesAreRefusedBeforeTheyAreMade) {
  std::string extension = R"([{"mesh": 0, "extensions": {"EXT_mesh_gpu_instancing": {
      "attributes": {"TRANSLATION": 1}}}}])";
  std::string text =
      triangle_gltf(extension, "[0]", R"("extensionsUsed": ["EXT_mesh_gpu_instancing"],)");
  // A second accessor, with no bufferView: 3 billion zero translations.
  text.replace(text.find("}],\n  \"meshes\""), 2,
               R"(}, {"componentType": 5126, "count": 3000000000, "type": "VEC3"}])");
  std::string gltf = dir_.write("many.gltf", text);
  expect_error("scene-info " + gltf, gltf + ": 3000000000 EXT_mesh_gpu_instancing instances need");
}

TEST_F(CliHostileScenes, AnOutputThatWouldReplaceAnInputIsRefused) {
  std::string scene = dir_.write("scene.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  std::string spec = dir_.write("w.toml", "scene = \"scene.obj\"\nresolution = \"16x9\"\n");
  expect_error("trace " + scene + " -q -o " + scene,
               scene + ": -o: is the same file as the scene (" + scene + ")");
  expect_error("trace " + spec + " -q -o " + dir_.path("./w.toml"),
               dir_.path("./w.toml") + ": -o: is the same file as the workload spec");
  fs::create_directory(dir_.path("sub"));
  expect_error("trace " + spec + " -q --preview " + dir_.path("sub/../scene.obj"),
               dir_.path("sub/../scene.obj") + ": --preview: is the same file as the scene");
  fs::create_symlink(scene, dir_.path("link.rays"));
  expect_error("trace " + spec + " -q -o " + dir_.path("link.rays"),
               dir_.path("link.rays") + ": -o: is the same file as the scene");
  std::string out = dir_.path("x.rays");
  expect_error("trace " + spec + " -q -o " + out + " --preview " + out,
               out + ": --preview: is the same file as -o (" + out + ")");
  expect_error("trace " + spec + " -q -o " + dir_.path("p.density-all.png") + " --preview " +
                   dir_.path("p.png"),
               dir_.path("p.density-all.png") + ": --preview: is the same file as -o");
  EXPECT_EQ(test::slurp(scene), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(files(), (std::vector<std::string>{"link.rays", "scene.obj", "sub", "w.toml"}))
      << "nothing written, no temporary left";
}

TEST_F(CliHostileScenes, AnOutputThatCannotBeWrittenIsRefusedBeforeTracing) {
  fs::create_directory(dir_.path("folder"));
  expect_error("trace cornell -q --preview " + dir_.path("folder"),
               dir_.path("folder") + ": --preview: is a folder; give a file path");
  expect_error(
      "trace cornell -q -o " + dir_.path("missing/x.rays"),
      dir_.path("missing/x.rays") + ": -o: its folder " + dir_.path("missing") + " does not exist");
  EXPECT_EQ(files(), std::vector<std::string>{"folder"});
}

TEST_F(CliHostileScenes, APreviewThatIsADeviceGetsThePictureOnly) {
  std::string null = dir_.path("null");
  if (mknod(null.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0)
    GTEST_SKIP() << "making a device node needs root";
  test::RunResult r = test::run_rtsim("trace cornell --resolution 16x9 -q --preview " + null);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(files(), std::vector<std::string>{"null"})
      << "no density image beside the device, no temporary";
  struct stat info {};
  ASSERT_EQ(stat(null.c_str(), &info), 0);
  EXPECT_TRUE(S_ISCHR(info.st_mode));
}

}  // namespace
}  // namespace rtsim
