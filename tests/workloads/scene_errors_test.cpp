// Bad input ends in one InputError line that names the file (or built-in spec) and the problem:
// missing files, unsupported extensions, NaN/Inf vertices, no triangles, garbage that assimp
// would otherwise accept, and bad triangle counts for the scalable built-ins.
#include <gtest/gtest.h>

#include "scene_test_util.h"

namespace rtsim {
namespace {

using test::expect_input_error;
using test::TempDir;

const char* kPlyHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\n"
    "property float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";

TEST(SceneErrors, MissingFileAndDirectory) {
  TempDir dir;
  expect_input_error(dir.path("nowhere.obj"), "no such file");
  std::filesystem::create_directories(dir.path("folder.obj"));
  expect_input_error(dir.path("folder.obj"), "is a directory");
}

TEST(SceneErrors, UnsupportedExtensionListsTheSupportedOnes) {
  TempDir dir;
  std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::string msg = expect_input_error(dir.write("mesh.fbx", triangle), "unsupported");
  EXPECT_NE(msg.find(".obj, .gltf, .glb, .ply, .off, .stl"), std::string::npos) << msg;
  expect_input_error(dir.write("mesh", triangle), "unsupported scene file extension ''");
  EXPECT_EQ(scene_file_extensions().size(), 6u);
}

TEST(SceneErrors, AVertexBeyondTheTracedRangeNamesTheVertexAndTheBound) {
  TempDir dir;
  expect_input_error(dir.write("huge.obj", "v 0 0 0\nv 1 0 0\nv 1e19 1 0\nf 1 2 3\n"),
                     "vertex 2: position (1e+19, 1, 0) is beyond +-1e+15");
  expect_input_error(dir.write("far.obj", "v 0 0 0\nv 1 0 0\nv 0 -1e18 0\nf 1 2 3\n"),
                     "vertex 2: position (0, -1e+18, 0) is beyond +-1e+15");
}

TEST(SceneErrors, NanOrInfVertexNamesTheVertex) {
  TempDir dir;
  expect_input_error(dir.write("nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n"),
                     "vertex 2: position (nan, 1, 0) is NaN or Inf");
  expect_input_error(
      dir.write("nan.ply", std::string(kPlyHeader) + "0 0 0\n1 0 0\nnan 1 0\n3 0 1 2\n"),
      "vertex 2: position (nan, 1, 0) is NaN or Inf");
  expect_input_error(dir.write("inf.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 inf 0\n3 0 1 2\n"),
                     "vertex 3: position (0, inf, 0) is NaN or Inf");
  // A vertex no triangle uses is still a broken file.
  expect_input_error(dir.write("unused.ply",
                               "ply\nformat ascii 1.0\nelement vertex 4\n"
                               "property float x\nproperty float y\n"
                               "property float z\nelement face 1\n"
                               "property list uchar int vertex_indices\n"
                               "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 -inf\n"
                               "3 0 1 2\n"),
                     "vertex 3");
}

TEST(SceneErrors, NoTriangles) {
  TempDir dir;
  expect_input_error(dir.write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"), "no triangles");
  expect_input_error(dir.write("lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n"),
                     "no triangles");
  expect_input_error(dir.write("text.obj", "this is not a scene\n"), "no triangles");
  expect_input_error(dir.write("cloud.ply",
                               "ply\nformat ascii 1.0\nelement vertex 2\n"
                               "property float x\nproperty float y\n"
                               "property float z\nend_header\n0 0 0\n1 0 0\n"),
                     "no triangles");
}

TEST(SceneErrors, ParseFailuresCarryAssimpsMessage) {
  TempDir dir;
  expect_input_error(dir.write("empty.obj", ""), "cannot import: OBJ-file is too small");
  expect_input_error(dir.write("bad.ply", "hello\n"), "cannot import: Invalid .ply file");
  expect_input_error(dir.write("bad.stl", "hello\n"), "cannot import");
  expect_input_error(dir.write("bad.off", "hello, this is no OFF file\n"),
                     "cannot import: OFF: Header is invalid");
  expect_input_error(dir.write("bad.gltf", "{ not json"), "cannot import");
  expect_input_error(dir.write("bad.glb", "glTF garbage"), "cannot import");
  expect_input_error(dir.write("index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"),
                     "vertex index out of range");
}

TEST(SceneErrors, GarbageThatAssimpRepairsIsRejected) {
  TempDir dir;
  // assimp's OFF reader clamps the index 7 to 2 and only logs an error.
  expect_input_error(dir.write("index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"),
                     "Vertex index is out of range");
  // Five vertices promised, three given: the reader pads with (0, 0, 0) and logs an error.
  expect_input_error(dir.write("short.off", "OFF\n5 1 0\n0 0 0\n1 0 0\n0 1 0\n"),
                     "number of verts in the header is incorrect");
}

TEST(SceneErrors, BadBuiltinParameters) {
  expect_input_error("grid:abc", "got 'abc'", "builtin:grid:abc");
  expect_input_error("grid:0", "from 1 to 1000000000", "builtin:grid:0");
  expect_input_error("builtin:foliage:1000000001", "got '1000000001'",
                     "builtin:foliage:1000000001");
  expect_input_error("foliage:-5", "got '-5'", "builtin:foliage:-5");
  expect_input_error("grid:1e6", "got '1e6'", "builtin:grid:1e6");
  expect_input_error("grid:", "got ''", "builtin:grid:");
  expect_input_error("foliage:99999999999999999999999", "whole number",
                     "builtin:foliage:99999999999999999999999");
  expect_input_error("grid", "needs a triangle count", "builtin:grid");
  expect_input_error("builtin:sponza", "unknown built-in scene; the built-ins are cornell, pica",
                     "builtin:sponza");
  expect_input_error("cornell:2", "unknown built-in scene", "builtin:cornell:2");
}

TEST(SceneErrors, FinalizeChecksTheInvariants) {
  Scene s;
  s.source = "handmade";
  EXPECT_THROW(finalize_scene(s), InputError) << "no triangles";
  s.mesh.positions = {glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f)};
  s.mesh.triangles = {{0, 1, 2}};
  s.materials = {Material{"m"}};
  s.object_names = {"o"};
  s.material_ids = {0};
  s.object_ids = {1};
  try {
    finalize_scene(s);
    ADD_FAILURE() << "object id 1 of 1 names should fail";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "handmade: triangle 0: object id 1 out of range");
  }
  s.object_ids = {0};
  s.mesh.triangles = {{0, 1, 3}};
  EXPECT_THROW(finalize_scene(s), InputError) << "vertex index 3 of 3";
  s.mesh.triangles = {{0, 1, 2}};
  finalize_scene(s);
  EXPECT_EQ(s.fingerprint, mesh_fingerprint(s.mesh));
  EXPECT_EQ(s.bounds.hi, glm::vec3(1.0f, 1.0f, 0.0f));
}

}  // namespace
}  // namespace rtsim
