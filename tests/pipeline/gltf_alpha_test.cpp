// glTF alphaMode MASK: the base colour texture's alpha (a PNG beside the file or in a data URI,
// read through OpenImageIO) against alphaCutoff makes holes where rays go through, placed by
// TEXCOORD_0 as glTF places texture coordinates (v down from the image's top row).
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cstring>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "tests/workloads/scene_test_util.h"
#include "traces/embree_scene.h"
#include "workloads/pipeline/image_io.h"

namespace rtsim {
namespace {

using test::base64;
using test::TempDir;

// A 2x2 RGBA PNG whose alphas are, row by row from the top, `alpha`; its bytes.
std::string write_png(const std::string& path, const std::array<uint8_t, 4>& alpha) {
  std::vector<uint8_t> rgba;
  for (uint8_t a : alpha) rgba.insert(rgba.end(), {200, 100, 50, a});
  auto out = OIIO::ImageOutput::create(path);
  OIIO::ImageSpec spec(2, 2, 4, OIIO::TypeDesc::UINT8);
  EXPECT_TRUE(out && out->open(path, spec) &&
              out->write_image(OIIO::TypeDesc::UINT8, rgba.data()) && out->close());
  std::ifstream in(path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// The quad [0, 2]^2 at z = 0, texture coordinates (x / 2, y / 2) (none without uv), in a
// material of alphaMode MASK whose base colour texture is the image at `image_uri`.
std::string fence_gltf(const std::string& image_uri, float cutoff, bool uv = true) {
  const float positions[12] = {0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0};
  const float uvs[8] = {0, 0, 1, 0, 1, 1, 0, 1};
  const uint16_t indices[6] = {0, 1, 2, 0, 2, 3};
  std::string data(92, '\0');
  std::memcpy(data.data(), positions, 48);
  std::memcpy(data.data() + 48, uvs, 32);
  std::memcpy(data.data() + 80, indices, 12);
  return fmt::format(R"({{
  "asset": {{"version": "2.0"}}, "scene": 0, "scenes": [{{"nodes": [0]}}],
  "nodes": [{{"name": "fence", "mesh": 0}}],
  "meshes": [{{"name": "quad", "primitives": [{{"attributes": {{"POSITION": 0{}}},
                                              "indices": 2, "material": 0}}]}}],
  "materials": [{{"name": "chain_link", "alphaMode": "MASK", "alphaCutoff": {},
                 "pbrMetallicRoughness": {{"baseColorTexture": {{"index": 0}}}}}}],
  "textures": [{{"source": 0}}],
  "images": [{{"uri": "{}"}}],
  "buffers": [{{"byteLength": 92, "uri": "data:application/octet-stream;base64,{}"}}],
  "bufferViews": [{{"buffer": 0, "byteOffset": 0, "byteLength": 48}},
                  {{"buffer": 0, "byteOffset": 48, "byteLength": 32}},
                  {{"buffer": 0, "byteOffset": 80, "byteLength": 12}}],
  "accessors": [
    {{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
     "min": [0, 0, 0], "max": [2, 2, 0]}},
    {{"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"}},
    {{"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}}
  ]
}})",
                     uv ? R"(, "TEXCOORD_0": 1)" : "", cutoff, image_uri, base64(data));
}

// Whether a ray down the z axis at (x, y) hits the quad.
bool hits(const EmbreeScene& embree, float x, float y) {
  Ray ray;
  ray.org = {x, y, 1.0f};
  ray.dir = {0.0f, 0.0f, -1.0f};
  return embree.intersect(ray).hit();
}

class GltfAlpha : public ::testing::Test {
 protected:
  void SetUp() override { set_alpha_image_reader(pipeline::read_texture_alpha); }
  TempDir dir;
};

TEST_F(GltfAlpha, RaysPassWhereTheTextureAlphaIsBelowTheCutoff) {
  // Top row: opaque, clear; bottom row: clear, half.
  std::string png = write_png(dir.path("fence.png"), {255, 0, 0, 128});
  for (const std::string& uri :
       {std::string("fence.png"), "data:image/png;base64," + base64(png)}) {
    SCOPED_TRACE(uri.substr(0, 20));
    for (float cutoff : {0.4f, 0.6f}) {
      Scene s = load_scene(dir.write("fence.gltf", fence_gltf(uri, cutoff)));
      ASSERT_TRUE(s.mesh.alpha);
      const AlphaMask& mask = *s.mesh.alpha->masks.at(0);
      EXPECT_EQ(mask.width, 2u);
      EXPECT_EQ(mask.cutoff, cutoff);
      EXPECT_EQ(mask.texture_offset, 0u);
      EmbreeScene embree(s.mesh, 1);
      EXPECT_TRUE(hits(embree, 0.5f, 0.5f)) << "v = 0 is the image's top row";
      EXPECT_FALSE(hits(embree, 1.5f, 0.5f));
      EXPECT_FALSE(hits(embree, 0.5f, 1.5f));
      EXPECT_EQ(hits(embree, 1.5f, 1.5f), cutoff < 0.5f) << "alpha 128 against the cutoff";
    }
  }
}

TEST_F(GltfAlpha, AMissingTextureOrTexCoordIsAnErrorNamingIt) {
  std::string gltf = dir.write("fence.gltf", fence_gltf("nowhere.png", 0.5f));
  test::expect_input_error(gltf, "", dir.path("nowhere.png"));
  write_png(dir.path("fence.png"), {255, 0, 0, 255});
  gltf = dir.write("bare.gltf", fence_gltf("fence.png", 0.5f, false));
  test::expect_input_error(gltf,
                           "mesh 'quad': its material is alphaMode MASK but it has no "
                           "TEXCOORD_0");
}

}  // namespace
}  // namespace rtsim
