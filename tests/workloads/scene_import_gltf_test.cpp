// glTF 2.0 (.gltf with an embedded buffer, and .glb): node transforms and instancing are applied,
// the instance structure is kept beside the flattened mesh, nodes name the objects, and
// metallic-roughness materials with their extensions map directly.
#include <gtest/gtest.h>

#include <cstring>

#include "scene_test_util.h"

namespace rtsim {
namespace {

using test::TempDir;

std::string base64(const std::string& in) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < in.size(); i += 3) {
    size_t left = in.size() - i;
    uint32_t n = uint32_t(uint8_t(in[i])) << 16;
    if (left > 1) n |= uint32_t(uint8_t(in[i + 1])) << 8;
    if (left > 2) n |= uint32_t(uint8_t(in[i + 2]));
    out += table[(n >> 18) & 63];
    out += table[(n >> 12) & 63];
    out += left > 1 ? table[(n >> 6) & 63] : '=';
    out += left > 2 ? table[n & 63] : '=';
  }
  return out;
}

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

TEST(SceneImportGltf, Base64EncoderMatchesKnownValues) {
  EXPECT_EQ(base64("M"), "TQ==");
  EXPECT_EQ(base64("Ma"), "TWE=");
  EXPECT_EQ(base64("Man"), "TWFu");
  EXPECT_EQ(base64("Many"), "TWFueQ==");
}

}  // namespace
}  // namespace rtsim
