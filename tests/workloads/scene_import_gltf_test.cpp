// glTF 2.0 (.gltf with an embedded buffer, and .glb): node transforms and instancing are applied,
// the instance structure is kept beside the flattened mesh, nodes name the objects,
// metallic-roughness materials with their extensions map directly, and EXT_mesh_gpu_instancing
// places a node's mesh once per instance.
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <limits>

#include <fmt/format.h>

#include "scene_test_util.h"

namespace rtsim {
namespace {

using test::base64;
using test::expect_input_error;
using test::TempDir;

// One triangle (0,0,0) (1,0,0) (0,1,0) as float positions and uint16 indices: 42 bytes.
std::string triangle_buffer() {
  const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const uint16_t indices[3] = {0, 1, 2};
  std::string data(42, '\0');
  std::memcpy(data.data(), positions, 36);
  std::memcpy(data.data() + 36, indices, 6);
  return data;
}

// The buffer (buffer: its uri field, or "" for a GLB's BIN chunk), views and accessors of
// triangle_buffer(), as the last members of a glTF document.
std::string triangle_accessors(const std::string& buffer) {
  return R"("buffers": [{"byteLength": 42)" + buffer + R"(}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                  {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
     "min": [0, 0, 0], "max": [1, 1, 0]},
    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}
  ]
)";
}

// Nodes: "left" at x = -2 and its instance "left_copy" at z = -3 share mesh 0; "child" (mesh 1)
// sits at z = 1 under "parent", which is at x = 10 and scaled by 2.
std::string gltf_json(const std::string& buffer) {
  return R"({
  "asset": {"version": "2.0"},
  "extensionsUsed": ["KHR_materials_transmission", "KHR_materials_ior",
                     "KHR_materials_clearcoat"],
  "scene": 0,
  "scenes": [{"nodes": [0, 1, 3]}],
  "nodes": [
    {"name": "left", "mesh": 0, "translation": [-2, 0, 0]},
    {"name": "parent", "translation": [10, 0, 0], "scale": [2, 2, 2], "children": [2]},
    {"name": "child", "mesh": 1, "translation": [0, 0, 1]},
    {"name": "left_copy", "mesh": 0, "translation": [-2, 0, -3]}
  ],
  "meshes": [
    {"name": "tri", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]},
    {"name": "tri2", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 1}]}
  ],
  "materials": [
    {"name": "red_metal", "emissiveFactor": [1, 0.5, 0.25],
     "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.1, 0.1, 1], "metallicFactor": 1,
                              "roughnessFactor": 0.2}},
    {"name": "coated_glass",
     "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0,
                              "roughnessFactor": 0},
     "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1},
                    "KHR_materials_ior": {"ior": 1.45},
                    "KHR_materials_clearcoat": {"clearcoatFactor": 1}}}
  ],
  )" + triangle_accessors(buffer) +
         "}";
}

void expect_scene(const Scene& s) {
  ASSERT_EQ(s.triangle_count(), 3u);
  EXPECT_EQ(s.object_names, (std::vector<std::string>{"left", "child", "left_copy"}));
  EXPECT_EQ(s.bounds.lo, glm::vec3(-2.0f, 0.0f, -3.0f));
  EXPECT_EQ(s.bounds.hi, glm::vec3(12.0f, 2.0f, 2.0f));
  // child: parent (translate 10, scale 2) applied to (translate z 1) applied to the triangle.
  FlatTriangles triangles = s.triangles();
  EXPECT_EQ(triangles.corners(1)[0], glm::vec3(10.0f, 0.0f, 2.0f));
  EXPECT_EQ(triangles.corners(1)[1], glm::vec3(12.0f, 0.0f, 2.0f));
  EXPECT_EQ(triangles.corners(2)[2], glm::vec3(-2.0f, 1.0f, -3.0f));

  // The instance structure: "left" and "left_copy" place one mesh twice, so the scene keeps no
  // flattened copy; flattened, it is the scene's triangles, one for one.
  EXPECT_FALSE(s.flattened());
  ASSERT_EQ(s.instanced.instances.size(), 3u);
  EXPECT_EQ(s.instanced.meshes.size(), 2u);
  EXPECT_EQ(s.instanced.instances[0].mesh, s.instanced.instances[2].mesh);
  EXPECT_NE(s.instanced.instances[0].mesh, s.instanced.instances[1].mesh);
  EXPECT_EQ(s.instanced.unique_triangles(), 2u);
  EXPECT_EQ(s.instanced.instanced_triangles(), 3u);
  EXPECT_EQ(s.instanced.instances[1].to_world.linear, glm::mat3(2.0f));
  EXPECT_EQ(s.instanced.instances[1].to_world.offset, glm::vec3(10.0f, 0.0f, 2.0f));
  FlatMesh flat = flatten(s.instanced);
  ASSERT_EQ(flat.mesh.triangle_count(), s.triangle_count());
  for (size_t t = 0; t < s.triangle_count(); ++t)
    for (int corner = 0; corner < 3; ++corner)
      EXPECT_EQ(flat.mesh.vertex(t, corner), triangles.corners(t)[corner]) << t << " " << corner;

  auto material = [&](uint64_t t) { return s.attributes(triangles, t).material; };
  const Material& metal = s.materials[material(0)];
  EXPECT_EQ(metal.name, "red_metal");
  EXPECT_FLOAT_EQ(metal.base_color.x, 0.9f);
  EXPECT_FLOAT_EQ(metal.metalness, 1.0f);
  EXPECT_FLOAT_EQ(metal.roughness, 0.2f);
  EXPECT_FLOAT_EQ(metal.emission.y, 0.5f);
  EXPECT_EQ(metal.transmission, 0.0f);
  EXPECT_EQ(metal.layers, 1);
  EXPECT_EQ(material(2), material(0));
  EXPECT_EQ(s.object_names[s.attributes(triangles, 2).object], "left_copy");
  const Material& glass = s.materials[material(1)];
  EXPECT_EQ(glass.name, "coated_glass");
  EXPECT_FLOAT_EQ(glass.transmission, 1.0f);
  EXPECT_FLOAT_EQ(glass.ior, 1.45f);
  EXPECT_EQ(glass.roughness, 0.0f);
  EXPECT_EQ(glass.layers, 2) << "clear coat";
}

TEST(SceneImportGltf, EmbeddedGltfAppliesNodeTransforms) {
  TempDir dir;
  std::string json = gltf_json(R"(, "uri": "data:application/octet-stream;base64,)" +
                               base64(triangle_buffer()) + "\"");
  expect_scene(load_scene(dir.write("nodes.gltf", json)));
}

TEST(SceneImportGltf, BinaryGlbMatchesTheTextForm) {
  TempDir dir;
  std::string json = gltf_json("");
  json.append((4 - json.size() % 4) % 4, ' ');
  std::string bin = triangle_buffer();
  bin.append((4 - bin.size() % 4) % 4, '\0');
  auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  std::string glb = "glTF" + u32(2) + u32(uint32_t(12 + 8 + json.size() + 8 + bin.size())) +
                    u32(uint32_t(json.size())) + "JSON" + json + u32(uint32_t(bin.size())) +
                    std::string("BIN\0", 4) + bin;
  expect_scene(load_scene(dir.write("nodes.glb", glb)));
}

// A triangle, a camera turned 90 degrees about y (looking along -x) and three punctual lights.
std::string gltf_with_view(const std::string& uri) {
  return R"({
  "asset": {"version": "2.0"},
  "extensionsUsed": ["KHR_lights_punctual"],
  "extensions": {"KHR_lights_punctual": {"lights": [
    {"name": "bulb", "type": "point", "color": [1, 0.5, 0.25], "intensity": 2},
    {"name": "lamp", "type": "spot", "intensity": 1, "spot": {"outerConeAngle": 0.5}},
    {"name": "sky", "type": "directional", "intensity": 3}]}},
  "scene": 0,
  "scenes": [{"nodes": [0, 1, 2, 3, 4]}],
  "nodes": [
    {"name": "tri", "mesh": 0},
    {"name": "eye", "camera": 0, "translation": [1, 2, 5],
     "rotation": [0, 0.70710678, 0, 0.70710678]},
    {"name": "bulb_node", "translation": [0, 3, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}},
    {"name": "lamp_node", "translation": [2, 0, 0], "extensions": {"KHR_lights_punctual": {"light": 1}}},
    {"name": "sun_node", "rotation": [-0.70710678, 0, 0, 0.70710678],
     "extensions": {"KHR_lights_punctual": {"light": 2}}}
  ],
  "cameras": [{"type": "perspective",
               "perspective": {"yfov": 0.8, "aspectRatio": 1.5, "znear": 0.1}}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  )" + triangle_accessors(R"(, "uri": ")" + uri + "\"") +
         "}";
}

void expect_near(const glm::vec3& a, const glm::vec3& b) {
  EXPECT_NEAR(a.x, b.x, 1e-5f);
  EXPECT_NEAR(a.y, b.y, 1e-5f);
  EXPECT_NEAR(a.z, b.z, 1e-5f);
}

TEST(SceneImportGltf, CamerasAndPunctualLightsArePlacedByTheirNodes) {
  TempDir dir;
  Scene s =
      load_scene(dir.write("view.gltf", gltf_with_view("data:application/octet-stream;base64," +
                                                       base64(triangle_buffer()))));
  ASSERT_EQ(s.triangle_count(), 1u);
  ASSERT_EQ(s.cameras.size(), 1u);
  const SceneCamera& eye = s.cameras[0];
  EXPECT_EQ(eye.name, "eye");
  expect_near(eye.position, {1, 2, 5});
  expect_near(eye.forward, {-1, 0, 0});
  expect_near(eye.up, {0, 1, 0});
  EXPECT_NEAR(eye.yfov_degrees, 0.8 * 180 / 3.14159265, 1e-3);
  ASSERT_EQ(s.lights.size(), 3u);
  EXPECT_EQ(s.lights[0].type, SceneLight::Type::Point);
  expect_near(s.lights[0].position, {0, 3, 0});
  expect_near(s.lights[0].color, {2, 1, 0.5});  // colour times intensity
  EXPECT_EQ(s.lights[1].type, SceneLight::Type::Spot);
  expect_near(s.lights[1].position, {2, 0, 0});
  expect_near(s.lights[1].direction, {0, 0, -1});
  EXPECT_NEAR(s.lights[1].outer_cone_degrees, 0.5 * 180 / 3.14159265, 1e-3);
  EXPECT_EQ(s.lights[2].type, SceneLight::Type::Directional);
  expect_near(s.lights[2].direction, {0, -1, 0});  // -z turned -90 degrees about x
}

// An orthographic camera (glTF's xmag and ymag, as Debian's assimp-testmodels
// glTF2/cameras/Cameras.gltf has) is read as one, with its view box and no field of view.
TEST(SceneImportGltf, AnOrthographicCameraKeepsItsViewBox) {
  std::string doc =
      gltf_with_view("data:application/octet-stream;base64," + base64(triangle_buffer()));
  auto swap = [&doc](const std::string& from, const std::string& to) {
    size_t at = doc.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    doc.replace(at, from.size(), to);
  };
  swap(R"("nodes": [0, 1, 2, 3, 4])", R"("nodes": [0, 1, 2, 3, 4, 5])");
  swap(R"("extensions": {"KHR_lights_punctual": {"light": 2}}})",
       R"("extensions": {"KHR_lights_punctual": {"light": 2}}},
    {"name": "top", "camera": 1, "translation": [0, 9, 0]})");
  swap(R"("znear": 0.1}}],)", R"("znear": 0.1}},
              {"type": "orthographic",
               "orthographic": {"xmag": 4, "ymag": 2, "znear": 0.1, "zfar": 100}}],)");
  TempDir dir;
  Scene s = load_scene(dir.write("ortho.gltf", doc));
  ASSERT_EQ(s.cameras.size(), 2u);
  EXPECT_FALSE(s.cameras[0].orthographic);
  const SceneCamera& top = s.cameras[1];
  EXPECT_EQ(top.name, "top");
  EXPECT_TRUE(top.orthographic);
  EXPECT_FLOAT_EQ(top.xmag, 4.0f);
  EXPECT_FLOAT_EQ(top.ymag, 2.0f);
  expect_near(top.position, {0, 9, 0});
}

// glTF 1.0 is refused by its version, or, unversioned, by its collections keyed by id; any
// other document without a version too (assimp finds no reader for it), after its checks.
TEST(SceneImportGltf, Gltf1IsRefusedNamingTheVersion) {
  TempDir dir;
  expect_input_error(dir.write("old.gltf", R"({"asset": {"version": "1.0"}, "meshes": {}})"),
                     "asset.version: '1.0': glTF 1.0; rtsim reads glTF 2.0");
  expect_input_error(dir.write("old2.gltf", R"({"asset": {"version": "1.0.2"}})"),
                     "asset.version: '1.0.2': glTF 1.0; rtsim reads glTF 2.0");
  expect_input_error(dir.write("three.gltf", R"({"asset": {"version": "3.0"}})"),
                     "asset.version: '3.0': glTF 3.0; rtsim reads glTF 2.0");
  expect_input_error(dir.write("keyed.gltf", R"({"nodes": {"root": {}}, "meshes": []})"),
                     "nodes: an object keyed by id, as in glTF 1.0");
  std::string doc =
      gltf_with_view("data:application/octet-stream;base64," + base64(triangle_buffer()));
  const std::string asset = R"("asset": {"version": "2.0"},)";
  doc.replace(doc.find(asset), asset.size(), "");
  expect_input_error(dir.write("unversioned.gltf", doc),
                     "asset.version: missing; glTF 2.0 names its version there");
  EXPECT_EQ(load_scene(
                dir.write("versioned.gltf", gltf_with_view("data:application/octet-stream;base64," +
                                                           base64(triangle_buffer()))))
                .triangle_count(),
            1u);
}

// A node rotated by a quaternion and one placed by a column-major matrix: each instance's
// transform has the node's columns (images of x, y, z) and offset, and flattens to the mesh.
TEST(SceneImportGltf, RotatedAndMatrixNodesKeepTheirColumns) {
  TempDir dir;
  std::string json = R"({
  "asset": {"version": "2.0"},
  "scene": 0,
  "scenes": [{"nodes": [0, 1]}],
  "nodes": [
    {"name": "turned", "mesh": 0, "rotation": [0, 0, 0.70710678, 0.70710678]},
    {"name": "placed", "mesh": 0, "matrix": [0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 5, 6, 7, 1]}
  ],
  "meshes": [{"name": "tri", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  )" +
                     triangle_accessors(R"(, "uri": "data:application/octet-stream;base64,)" +
                                        base64(triangle_buffer()) + "\"") +
                     "}";
  Scene s = load_scene(dir.write("turned.gltf", json));
  ASSERT_EQ(s.instanced.instances.size(), 2u);
  ASSERT_EQ(s.instanced.meshes.size(), 1u);
  const Transform& turned = s.instanced.instances[0].to_world;
  // 90 degrees about +z: x goes to y, y to -x.
  EXPECT_NEAR(turned.linear[0].y, 1.0f, 1e-6f);
  EXPECT_NEAR(turned.linear[1].x, -1.0f, 1e-6f);
  EXPECT_NEAR(turned.linear[2].z, 1.0f, 1e-6f);
  const Transform& placed = s.instanced.instances[1].to_world;
  EXPECT_EQ(placed.linear[0], glm::vec3(0, 0, -1));
  EXPECT_EQ(placed.linear[1], glm::vec3(0, 1, 0));
  EXPECT_EQ(placed.linear[2], glm::vec3(1, 0, 0));
  EXPECT_EQ(placed.offset, glm::vec3(5, 6, 7));
  FlatTriangles triangles = s.triangles();
  EXPECT_EQ(triangles.corners(1)[1], glm::vec3(5, 6, 6)) << "(1,0,0) through the matrix";
  EXPECT_NEAR(triangles.corners(0)[2].x, -1.0f, 1e-6f) << "(0,1,0) turned to -x";
}

// A document with the one-triangle mesh (mesh 0; accessors 0 and 1) and the accessors that
// add() appends (2, 3, ...), all in one embedded buffer.
class InstancingGltf {
 public:
  // An accessor of `type` ("VEC3", "VEC4") holding the floats; its index.
  int add(const std::string& type, const std::vector<float>& values) {
    size_t components = type == "VEC4" ? 4 : 3;
    return add(
        type, 5126,
        std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(float)),
        values.size() / components);
  }

  // An accessor of count elements of `type` and component_type (normalized if an integer type)
  // whose bytes are `bytes`; its index.
  int add(const std::string& type, int component_type, const std::string& bytes, size_t count) {
    views_ += fmt::format(R"(, {{"buffer": 0, "byteOffset": {}, "byteLength": {}}})", data_.size(),
                          bytes.size());
    accessors_ +=
        fmt::format(R"(, {{"bufferView": {}, "componentType": {}, "count": {}, "type": "{}"{}}})",
                    accessor_count_, component_type, count, type,
                    component_type == 5126 ? "" : R"(, "normalized": true)");
    data_ += bytes;
    data_.append((4 - data_.size() % 4) % 4, '\0');
    return accessor_count_++;
  }

  // The document: scene 0 has the root nodes `roots` (a JSON array) of `nodes`.
  std::string json(const std::string& roots, const std::string& nodes) const {
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": )" + roots +
           R"(}], "nodes": )" + nodes + R"(,
  "meshes": [{"name": "tri", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "buffers": [{"byteLength": )" +
           std::to_string(data_.size()) + R"(, "uri": "data:application/octet-stream;base64,)" +
           base64(data_) + R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                  {"buffer": 0, "byteOffset": 36, "byteLength": 6})" +
           views_ + R"(],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                 "min": [0, 0, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"})" +
           accessors_ + "]}";
  }

 private:
  std::string data_ = triangle_buffer() + std::string(2, '\0');
  std::string views_, accessors_;
  int accessor_count_ = 2;
};

std::string gpu_instancing(const std::string& attributes) {
  return R"("extensions": {"EXT_mesh_gpu_instancing": {"attributes": {)" + attributes + "}}}";
}

void expect_corners(const FlatTriangles& triangles, uint64_t tri,
                    const std::array<glm::vec3, 3>& expected) {
  for (int corner = 0; corner < 3; ++corner) {
    SCOPED_TRACE(fmt::format("triangle {} corner {}", tri, corner));
    expect_near(triangles.corners(tri)[corner], expected[corner]);
  }
}

// An unnamed node with three instances (translation x rotation x scale each) under a named
// parent that translates and scales, beside a named node that places the mesh once: the
// instances come first in flat order, each in the parent's frame.
TEST(SceneImportGltf, GpuInstancingPlacesTheMeshOncePerInstance) {
  const float h = 0.70710678f;
  InstancingGltf gltf;
  int translation = gltf.add("VEC3", {1, 0, 0, 0, 2, 0, 0, 0, 3});
  int rotation = gltf.add("VEC4", {0, 0, 0, 1, 0, 0, h, h, 1, 0, 0, 0});  // none, z 90, x 180
  int scale = gltf.add("VEC3", {1, 1, 1, 2, 2, 2, 1, 1, 3});
  std::string nodes =
      R"([
    {"name": "parent", "translation": [0, 0, 10], "scale": [2, 2, 2], "children": [1]},
    {"mesh": 0, )" +
      gpu_instancing(fmt::format(R"("TRANSLATION": {}, "ROTATION": {}, "SCALE": {})", translation,
                                 rotation, scale)) +
      R"(},
    {"name": "solo", "mesh": 0, "translation": [-5, 0, 0]}])";
  TempDir dir;
  Scene s = load_scene(dir.write("instanced.gltf", gltf.json("[0, 2]", nodes)));

  EXPECT_FALSE(s.flattened()) << "one mesh placed four times keeps no flattened copy";
  ASSERT_EQ(s.instanced.instances.size(), 4u);
  EXPECT_EQ(s.instanced.meshes.size(), 1u);
  EXPECT_EQ(s.triangle_count(), 4u);
  FlatTriangles triangles = s.triangles();
  // Each instance: parent (x2, then +10 z) after the instance's T x R x S.
  expect_corners(triangles, 0, {glm::vec3(2, 0, 10), glm::vec3(4, 0, 10), glm::vec3(2, 2, 10)});
  expect_corners(triangles, 1, {glm::vec3(0, 4, 10), glm::vec3(0, 8, 10), glm::vec3(-4, 4, 10)});
  expect_corners(triangles, 2, {glm::vec3(0, 0, 16), glm::vec3(2, 0, 16), glm::vec3(0, -2, 16)});
  expect_corners(triangles, 3, {glm::vec3(-5, 0, 0), glm::vec3(-4, 0, 0), glm::vec3(-5, 1, 0)});
  EXPECT_EQ(s.object_names[s.attributes(triangles, 3).object], "solo");
  EXPECT_EQ(s.attributes(triangles, 0).object, s.attributes(triangles, 2).object);
}

// Only TRANSLATION: the instances keep the node's rotation and scale. The node's child, named
// like it, is placed once: nodes are matched by their place in the tree, not by name.
TEST(SceneImportGltf, GpuInstancingWithTranslationsOnly) {
  InstancingGltf gltf;
  int translation = gltf.add("VEC3", {0, 0, 0, 3, 0, 0});
  std::string nodes = R"([
    {"name": "row", "mesh": 0, "translation": [0, 5, 0], "children": [1], )" +
                      gpu_instancing(fmt::format(R"("TRANSLATION": {})", translation)) + R"(},
    {"name": "row", "mesh": 0, "translation": [0, 0, -7]}])";
  TempDir dir;
  Scene s = load_scene(dir.write("row.gltf", gltf.json("[0]", nodes)));
  EXPECT_FALSE(s.flattened());
  ASSERT_EQ(s.instanced.instances.size(), 3u);
  EXPECT_EQ(s.triangle_count(), 3u);
  const std::vector<Instance>& instances = s.instanced.instances;
  EXPECT_EQ(instances[0].to_world.offset, glm::vec3(0, 5, 0));
  EXPECT_EQ(instances[1].to_world.offset, glm::vec3(3, 5, 0));
  EXPECT_EQ(instances[2].to_world.offset, glm::vec3(0, 5, -7)) << "the child: not instanced";
  for (const Instance& instance : instances) EXPECT_EQ(instance.to_world.linear, glm::mat3(1.0f));
}

// A normalized BYTE rotation (quantized, so only close to unit length) of a single instance:
// the mesh is placed once, so the scene stays flattened.
TEST(SceneImportGltf, GpuInstancingReadsNormalizedByteRotations) {
  InstancingGltf gltf;
  const int8_t quarter_turn_z[4] = {0, 0, 127, 127};
  int rotation =
      gltf.add("VEC4", 5120, std::string(reinterpret_cast<const char*>(quarter_turn_z), 4), 1);
  std::string nodes = R"([{"name": "turned", "mesh": 0, )" +
                      gpu_instancing(fmt::format(R"("ROTATION": {})", rotation)) + "}]";
  TempDir dir;
  Scene s = load_scene(dir.write("turned.gltf", gltf.json("[0]", nodes)));
  EXPECT_TRUE(s.flattened());
  ASSERT_EQ(s.triangle_count(), 1u);
  expect_corners(s.triangles(), 0, {glm::vec3(0, 0, 0), glm::vec3(0, 1, 0), glm::vec3(-1, 0, 0)});
}

// Broken extension data: one InputError line naming the file, the node and the attribute.
TEST(SceneImportGltf, GpuInstancingErrorsNameTheNodeAndAttribute) {
  TempDir dir;
  auto file = [&](const std::string& name, InstancingGltf& gltf, const std::string& attributes) {
    std::string nodes = R"([{"name": "base"}, {"mesh": 0, )" + gpu_instancing(attributes) + "}]";
    return dir.write(name, gltf.json("[0, 1]", nodes));
  };
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();

  InstancingGltf counts;
  int three = counts.add("VEC3", {0, 0, 0, 1, 0, 0, 2, 0, 0});
  int two = counts.add("VEC3", {1, 1, 1, 1, 1, 1});
  expect_input_error(
      file("counts.gltf", counts, fmt::format(R"("TRANSLATION": {}, "SCALE": {})", three, two)),
      "node 1 EXT_mesh_gpu_instancing TRANSLATION: accessor 2 has 3 elements, SCALE's accessor "
      "3 has 2");

  InstancingGltf missing;
  missing.add("VEC3", {0, 0, 0});
  expect_input_error(file("missing.gltf", missing, R"("TRANSLATION": 2, "ROTATION": 9)"),
                     "node 1 EXT_mesh_gpu_instancing ROTATION: accessor 9 does not exist (the "
                     "file has 3)");

  InstancingGltf not_finite;
  int translation = not_finite.add("VEC3", {0, 0, 0, nan, 0, 0});
  int scale = not_finite.add("VEC3", {1, 1, 1, 1, inf, 1});
  expect_input_error(file("nan.gltf", not_finite, fmt::format(R"("TRANSLATION": {})", translation)),
                     "node 1 EXT_mesh_gpu_instancing TRANSLATION: instance 1 is (nan, 0, 0): NaN "
                     "or Inf");
  expect_input_error(file("inf.gltf", not_finite, fmt::format(R"("SCALE": {})", scale)),
                     "node 1 EXT_mesh_gpu_instancing SCALE: instance 1 is (1, inf, 1): NaN or Inf");

  InstancingGltf types;
  int vec4 = types.add("VEC4", {0, 0, 0, 1});
  int bytes = types.add("VEC3", 5121, std::string(4, '\1'), 1);
  expect_input_error(file("type.gltf", types, fmt::format(R"("TRANSLATION": {})", vec4)),
                     "TRANSLATION: accessor 2 is VEC4; it must be VEC3");
  expect_input_error(file("component.gltf", types, fmt::format(R"("SCALE": {})", bytes)),
                     "SCALE: accessor 3 has componentType 5121; it must be FLOAT (5126)");
}

TEST(SceneImportGltf, Base64EncoderMatchesKnownValues) {
  EXPECT_EQ(base64("M"), "TQ==");
  EXPECT_EQ(base64("Ma"), "TWE=");
  EXPECT_EQ(base64("Man"), "TWFu");
  EXPECT_EQ(base64("Many"), "TWFueQ==");
}

}  // namespace
}  // namespace rtsim
