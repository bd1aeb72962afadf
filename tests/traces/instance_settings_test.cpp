// Instance settings (issue 17): visibility masks and motion along keys, as the stream header
// records them and as Embree's reference traces them.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

#include "stream_test_util.h"
#include "traces/embree_scene.h"
#include "traces/error.h"
#include "traces/hash.h"
#include "traces/instance_settings.h"

namespace rtsim {
namespace {

InstanceSettings sample_settings() {
  InstanceSettings s;
  s.ray_masks[size_t(RayType::Shadow)] = 0x02;
  s.masks = {{1, 0x01}, {4, 0x03}};
  Motion m;
  m.axis = {0.0f, 0.0f, 1.0f};
  m.keys = {{{0.0f, 0.0f, 0.0f}, 0.0f, 1.0f}, {{4.0f, -1.0f, 0.5f}, 90.0f, 2.0f}};
  s.motions = {m};
  s.moving = {{0, 0}, {3, 0}};
  s.frames = 3;
  return s;
}

TEST(InstanceSettings, SurviveTheStreamHeader) {
  std::string path = test::temp_path("settings.rays");
  StreamHeader header = test::sample_header();
  header.instances = sample_settings();
  RayStreamWriter writer(path, header);
  writer.write(test::sample_rays(1)[0]);
  writer.finish();
  RayStreamReader reader(path);
  EXPECT_TRUE(reader.header().instances == sample_settings());  // frames: the frame count
  std::remove(path.c_str());
}

TEST(InstanceSettings, VersionOneStreamsReadWithoutSettings) {
  std::string path = test::temp_path("v1.rays");
  test::write_stream(path, test::sample_rays(10));
  std::vector<uint8_t> bytes = test::read_bytes(path);
  // Version 1: the same header without the (empty, 20-byte) settings section.
  uint32_t header_bytes;
  std::memcpy(&header_bytes, bytes.data() + 12, 4);
  bytes.erase(bytes.begin() + (header_bytes - 24), bytes.begin() + (header_bytes - 4));
  header_bytes -= 20;
  uint32_t version = 1;
  std::memcpy(bytes.data() + 8, &version, 4);
  std::memcpy(bytes.data() + 12, &header_bytes, 4);
  uint32_t crc = crc32(bytes.data(), header_bytes - 4);
  std::memcpy(bytes.data() + header_bytes - 4, &crc, 4);
  test::write_bytes(path, bytes);
  StreamHeader header;
  EXPECT_EQ(read_all_rays(path, &header).size(), 10u);
  EXPECT_TRUE(header.instances.empty());
  std::remove(path.c_str());
}

TEST(InstanceSettings, ProblemsNameWhatIsWrong) {
  auto problem = [](auto edit) {
    InstanceSettings s = sample_settings();
    edit(s);
    return settings_problem(s, 5);
  };
  EXPECT_EQ(problem([](InstanceSettings&) {}), "");
  EXPECT_EQ(problem([](InstanceSettings& s) { s.ray_masks[size_t(RayType::AO)] = 0; }),
            "ao rays have inclusion mask 0 (they would see nothing)");
  EXPECT_EQ(problem([](InstanceSettings& s) {
              s.masks.push_back({5, 1});
            }),
            "a mask of instance 5, of 5 instances");
  EXPECT_EQ(problem([](InstanceSettings& s) { std::swap(s.moving[0], s.moving[1]); }),
            "a motion of instance 0 out of order");
  EXPECT_EQ(problem([](InstanceSettings& s) { s.moving[1].second = 1; }),
            "instance 3 moves by motion 1 of 1");
  EXPECT_EQ(problem([](InstanceSettings& s) { s.motions[0].keys.clear(); }),
            "motion 0 has no keys");
  EXPECT_EQ(problem([](InstanceSettings& s) {
              s.motions[0].axis = {1.0f, 1.0f, 0.0f};
            }),
            "motion 0 has an axis that is not of unit length");
  EXPECT_EQ(problem([](InstanceSettings& s) { s.motions[0].keys[1].scale = 0.0f; }),
            "motion 0 key 1 has scale 0, not positive");
}

TEST(InstanceSettings, PosesFollowTheKeysAboutTheInstancesOrigin) {
  Transform placed;
  placed.offset = {10.0f, 0.0f, 0.0f};
  Motion m;  // about +y
  m.keys = {{}, {{0.0f, 2.0f, 0.0f}, 90.0f, 1.0f}, {{0.0f, 4.0f, 0.0f}, 90.0f, 3.0f}};
  // Five frames over three keys: frame 2 is key 1, frame 1 halfway to it.
  Transform at2 = pose_at(placed, m, 2, 5);
  glm::vec3 p = at2.point({1.0f, 0.0f, 0.0f});  // turned a quarter about its own origin
  EXPECT_NEAR(p.x, 10.0f, 1e-6f);
  EXPECT_NEAR(p.y, 2.0f, 1e-6f);
  EXPECT_NEAR(p.z, -1.0f, 1e-6f);
  glm::vec3 half = pose_at(placed, m, 1, 5).point({0.0f, 0.0f, 0.0f});
  EXPECT_FLOAT_EQ(half.y, 1.0f);
  EXPECT_FLOAT_EQ(pose_at(placed, m, 4, 5).point({0.0f, 0.0f, 1.0f}).x, 13.0f);  // scale 3
  EXPECT_FLOAT_EQ(pose_at(placed, m, 9, 5).offset.y, 4.0f);  // past the last frame: the last key
}

// One unit triangle in the z = 0 plane, placed at z = 1 (instance 0) and z = 3 (instance 1).
InstancedMesh two_walls() {
  InstancedMesh g;
  TriangleMesh tri;
  tri.positions = {{-1.0f, -1.0f, 0.0f}, {3.0f, -1.0f, 0.0f}, {-1.0f, 3.0f, 0.0f}};
  tri.triangles = {{0, 1, 2}};
  g.meshes = {tri};
  g.instances = {{0, {}}, {0, {}}};
  g.instances[0].to_world.offset.z = 1.0f;
  g.instances[1].to_world.offset.z = 3.0f;
  return g;
}

Ray ray_along_z(RayType type, uint32_t frame = 0) {
  Ray r;
  r.type = type;
  r.frame = frame;
  return r;
}

TEST(InstanceSettings, EmbreeSkipsInstancesTheRayTypeDoesNotSee) {
  InstancedMesh g = two_walls();
  InstanceSettings s;
  s.masks = {{0, 0x01}};
  s.ray_masks[size_t(RayType::Shadow)] = 0x02;  // does not see instance 0
  apply_masks(g, s);
  EmbreeScene embree(g, s, 1);
  Hit camera = embree.intersect(ray_along_z(RayType::Camera));
  EXPECT_EQ(camera.instance, 0u);
  EXPECT_FLOAT_EQ(camera.t, 1.0f);
  Hit shadow = embree.intersect(ray_along_z(RayType::Shadow));
  EXPECT_EQ(shadow.instance, 1u);
  EXPECT_FLOAT_EQ(shadow.t, 3.0f);
}

TEST(InstanceSettings, EmbreeTracesEachFrameInItsOwnPose) {
  InstancedMesh g = two_walls();
  InstanceSettings s;
  Motion slide;  // instance 0 moves out of the ray's way, then back beyond instance 1
  slide.keys = {{}, {{10.0f, 0.0f, 0.0f}, 0.0f, 1.0f}, {{0.0f, 0.0f, 4.0f}, 0.0f, 1.0f}};
  s.motions = {slide};
  s.moving = {{0, 0}};
  s.frames = 3;
  s.still_frames = 2;
  EmbreeScene embree(g, s, 1);
  EXPECT_EQ(embree.top_build_seconds().size(), 3u);
  for (uint32_t warmup = 0; warmup <= 2; ++warmup)
    EXPECT_EQ(embree.intersect(ray_along_z(RayType::Camera, warmup)).instance, 0u);
  EXPECT_EQ(embree.intersect(ray_along_z(RayType::Camera, 3)).instance, 1u);
  Hit last = embree.intersect(ray_along_z(RayType::Camera, 4));
  EXPECT_EQ(last.instance, 1u);
  EXPECT_FLOAT_EQ(last.t, 3.0f);
  EXPECT_TRUE(embree.occluded(ray_along_z(RayType::Shadow, 7)));
}

}  // namespace
}  // namespace rtsim
