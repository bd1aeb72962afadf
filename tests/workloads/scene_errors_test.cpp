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
  expect_input_error(dir.write("bad.glb", "garbage that is not glTF"),
                     "offset 0: not a GLB file (it does not begin with 'glTF')");
}

// OBJ indices are checked before assimp reads the file, so the message names the line.
TEST(SceneErrors, ObjIndicesOutOfRangeNameTheLine) {
  TempDir dir;
  std::string three = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expect_input_error(dir.write("index.obj", three + "f 1 2 9\n"),
                     "line 4: '9' refers to vertex 9, but only 3 vertices ('v' lines) are "
                     "defined above this line");
  expect_input_error(dir.write("early.obj", "v 0 0 0\nf 1 2 3\nv 1 0 0\nv 0 1 0\n"),
                     "line 2: '2' refers to vertex 2, but only 1 vertex ('v' lines)");
  expect_input_error(dir.write("back.obj", three + "# comment\nf -1 -2 -4\n"),
                     "line 5: '-4' refers to vertex -4");
  expect_input_error(dir.write("zero.obj", three + "f 0 1 2\n"),
                     "line 4: vertex index 0 in '0': OBJ indices start at 1");
  expect_input_error(dir.write("uv.obj", three + "vt 0 0\nf 1/1 2/2 3/1\n"),
                     "line 5: '2/2' refers to texture coordinate 2, but only 1 texture coordinate");
  expect_input_error(dir.write("normal.obj", three + "vn 0 0 1\nf 1//1 2//1 3//5\n"),
                     "line 5: '3//5' refers to normal 5");
  expect_input_error(dir.write("word.obj", three + "f 1 2 three\n"),
                     "line 4: 'three' is not an index of the form v, v/vt or v/vt/vn");
  expect_input_error(dir.write("line.obj", three + "f 1 2 3\nl 1 7\n"), "line 5: '7'");
  expect_input_error(dir.write("comment.obj", three + "f 1 2 3 # one\n"),
                     "line 4: a comment after the indices is not read");
  // Valid forms still load: relative indices, omitted texture coordinates, comments.
  TempDir ok;
  EXPECT_EQ(load_scene(ok.write("ok.obj", three + "vn 0 0 1\n# tri\nf -3//-1 -2//-1 -1//-1\n"))
                .triangle_count(),
            1u);
}

// glTF's JSON and the GLB container are checked before assimp, which only says "No suitable
// reader found" for a truncated document.
TEST(SceneErrors, GltfJsonAndGlbContainerErrorsNameThePlace) {
  TempDir dir;
  std::string msg = expect_input_error(
      dir.write("bad.gltf", "{\n  \"asset\": {\"version\": \"2.0\"},\n  \"nodes\": [\n"),
      "line 4: not valid JSON: ");
  EXPECT_EQ(msg.find("No suitable reader"), std::string::npos) << msg;
  expect_input_error(dir.write("word.gltf", "{ not json }"), "line 1: not valid JSON");
  std::string header("glTF\x02\0\0\0", 8);
  auto word = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  expect_input_error(dir.write("short.glb", header + word(100) + word(10)),
                     "shorter than its 12-byte header");
  std::string json = "{\"asset\": {\"version\": \"2.0\"}}";
  std::string chunk = word(uint32_t(json.size())) + word(0x4E4F534Au) + json;
  expect_input_error(dir.write("truncated.glb", header + word(500) + chunk),
                     "offset 8: the header says 500 bytes, the file has 49 (truncated?)");
  std::string v1 = std::string("glTF\x01\0\0\0", 8) + word(49) + chunk;
  expect_input_error(dir.write("v1.glb", v1), "offset 4: GLB version 1; rtsim reads glTF 2.0");
  std::string broken = "{\"asset\": {\"version\": \"2.0\"";
  std::string broken_chunk = word(uint32_t(broken.size())) + word(0x4E4F534Au) + broken;
  expect_input_error(
      dir.write("json.glb", header + word(uint32_t(20 + broken.size())) + broken_chunk),
      "not valid JSON");
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

// A triangle whose index is beyond its POSITION accessor: assimp would drop the faces and say
// only that the mesh "has no faces". The index data comes from a data: URI, a buffer file or
// the GLB's BIN chunk.
std::string triangle_gltf(const std::string& uri) {
  return "{\"asset\": {\"version\": \"2.0\"}, \"scene\": 0, \"scenes\": [{\"nodes\": [0]}],"
         "\"nodes\": [{\"mesh\": 0}], \"meshes\": [{\"primitives\": [{\"attributes\": "
         "{\"POSITION\": 0}, \"indices\": 1}]}], \"buffers\": [{\"byteLength\": 44" +
         (uri.empty() ? "" : ", \"uri\": \"" + uri + "\"") +
         "}], \"bufferViews\": [{\"buffer\": 0, \"byteLength\": 36}, {\"buffer\": 0, "
         "\"byteOffset\": 36, \"byteLength\": 6}], \"accessors\": [{\"bufferView\": 0, "
         "\"componentType\": 5126, \"count\": 3, \"type\": \"VEC3\", \"min\": [0, 0, 0], "
         "\"max\": [1, 1, 0]}, {\"bufferView\": 1, \"componentType\": 5123, \"count\": 3, "
         "\"type\": \"SCALAR\"}]}";
}

TEST(SceneErrors, GltfIndicesBeyondTheirVerticesNameThePrimitive) {
  TempDir dir;
  const char* bad = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAUAAAA=";
  const char* good = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA=";
  std::string what = "meshes[0].primitives[0]: index 2 of accessor 1 is 5, beyond the 3 vertices";
  std::string msg = expect_input_error(
      dir.write("uri.gltf",
                triangle_gltf(std::string("data:application/octet-stream;base64,") + bad)),
      what);
  EXPECT_EQ(msg.find("has no faces"), std::string::npos) << msg;
  // The same bytes (the triangle (0,0,0) (1,0,0) (0,1,0), indices 0 1 5) as a buffer file beside
  // the scene, and as a GLB's BIN chunk.
  const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const uint16_t indices[4] = {0, 1, 5, 0};
  std::string raw(reinterpret_cast<const char*>(positions), sizeof positions);
  raw.append(reinterpret_cast<const char*>(indices), sizeof indices);
  dir.write("tri.bin", raw);
  expect_input_error(dir.write("file.gltf", triangle_gltf("tri.bin")), what);
  std::string json = triangle_gltf("");
  while (json.size() % 4) json += ' ';
  auto word = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  std::string glb = word(uint32_t(json.size())) + word(0x4E4F534Au) + json +
                    word(uint32_t(raw.size())) + word(0x004E4942u) + raw;
  glb = std::string("glTF\x02\0\0\0", 8) + word(uint32_t(12 + glb.size())) + glb;
  expect_input_error(dir.write("bin.glb", glb), what);
  // In range, the same file loads.
  EXPECT_EQ(load_scene(dir.write("ok.gltf", triangle_gltf(std::string("data:application/"
                                                                      "octet-stream;base64,") +
                                                          good)))
                .triangle_count(),
            1u);
}

}  // namespace
}  // namespace rtsim
