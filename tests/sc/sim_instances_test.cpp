// Whole simulations of two-level BVHs (model/bvh/two_level.h): every ray of an instanced world
// retires with Embree's instanced answer in every traversal mode, the flattened world gives the
// same hits, and the per-level stats add up.
#include <gtest/gtest.h>

#include <random>

#include "tests/instanced_world.h"
#include "tests/sc/sim_test_util.h"

namespace rtsim {
namespace {

Scene instanced_scene(const InstancedMesh& geometry) {
  Scene scene;
  scene.source = "test:instanced";
  scene.mesh = flatten(geometry).mesh;
  scene.instanced = geometry;
  return scene;
}

// Closest-hit and any-hit rays through the world, some from inside its instances.
std::vector<Ray> world_rays(size_t n, uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<Ray> rays;
  for (size_t i = 0; i < n; ++i) {
    Ray ray = test::world_ray(rng);
    if (i % 3 == 2) {
      ray.query = Query::AnyHit;
      ray.type = RayType::Shadow;
      ray.tmax = 0.7f;
    }
    rays.push_back(ray);
  }
  return rays;
}

HwConfig machine(const char* mode, const char* instancing) {
  return load_hw_config("", {std::string("rt.mode=\"") + mode + "\"",
                             std::string("bvh.instancing=\"") + instancing + "\"",
                             "rt.transform.latency=5", "bvh.treelet_bytes=512"});
}

class SimInstances : public ::testing::TestWithParam<const char*> {};

TEST_P(SimInstances, EveryRayRetiresWithEmbreesInstancedAnswerAndTheLevelsAddUp) {
  Scene scene = instanced_scene(test::instanced_world());
  std::vector<Ray> rays = world_rays(3000, 5);
  HwConfig config = machine(GetParam(), "two_level");
  nlohmann::json doc = test::simulate(config, scene, rays, true);
  EXPECT_EQ(doc["verify"]["rays"], rays.size());
  EXPECT_EQ(doc["verify"]["unexplained"], 0) << doc["verify"].dump();
  EXPECT_EQ(doc["bvh"]["levels"], 2);
  EXPECT_EQ(doc["bvh"]["instances"], scene.instanced.instances.size());
  EXPECT_EQ(doc["bvh"]["triangles"], scene.instanced.unique_triangles());
  uint32_t units = config.rt_units;
  double nodes = 0, instances = 0, transforms = 0;
  for (uint32_t u = 0; u < units; ++u) {
    std::string p = "rt" + std::to_string(u);
    nodes += test::stat(doc, p + ".node_steps");
    instances += test::stat(doc, p + ".instance_steps");
    transforms += test::stat(doc, p + ".transform.tests");
  }
  EXPECT_GT(instances, rays.size() / 4.0) << "rays enter instances";
  EXPECT_EQ(test::stat(doc, "bvh.instance_steps"), instances);
  EXPECT_EQ(transforms, instances) << "one transform per instance entered";
  EXPECT_EQ(test::stat(doc, "bvh.top.node_steps") + test::stat(doc, "bvh.bottom.node_steps"),
            nodes);
  EXPECT_GT(test::stat(doc, "bvh.top.node_steps"), 0);
  EXPECT_GT(test::stat(doc, "bvh.bottom.node_steps"), 0);
  EXPECT_GT(test::stat(doc, "bvh.top.mem.l1.accesses"), 0);
  EXPECT_GT(test::stat(doc, "bvh.bottom.mem.l1.accesses"), 0);
  double typed = 0;
  for (auto& [name, t] : doc["ray_types"].items())
    typed += t["instances_per_ray"].get<double>() * t["rays"].get<double>();
  EXPECT_NEAR(typed, instances, 0.5) << "per-type transforms add up";
}

INSTANTIATE_TEST_SUITE_P(Modes, SimInstances,
                         ::testing::Values("depth_first", "treelet", "packet"));

TEST(SimInstancing, FlattenedAndInstancedWorldsGiveTheSameHits) {
  Scene scene = instanced_scene(test::instanced_world());
  std::vector<Ray> rays = world_rays(2000, 8);
  nlohmann::json flat = test::simulate(machine("depth_first", "flatten"), scene, rays, true);
  nlohmann::json two = test::simulate(machine("depth_first", "two_level"), scene, rays, true);
  EXPECT_EQ(flat["bvh"]["levels"], 1);
  EXPECT_EQ(flat["bvh"]["triangles"], scene.mesh.triangle_count());
  EXPECT_FALSE(flat["stats"]["counters"].contains("bvh.instance_steps"))
      << "one level reports no levels";
  EXPECT_EQ(flat["verify"]["unexplained"], 0);
  EXPECT_EQ(two["verify"]["unexplained"], 0);
  for (auto& [name, t] : flat["ray_types"].items())
    EXPECT_EQ(t["hits"], two["ray_types"][name]["hits"]) << name;
  // auto: two levels here (a mesh is placed more than once), one where each is placed once.
  nlohmann::json automatic = test::simulate(machine("depth_first", "auto"), scene, rays);
  EXPECT_EQ(automatic["bvh"]["levels"], 2);
  InstancedMesh once = test::instanced_world();
  once.instances.resize(1);
  once.instances.push_back({1, once.instances[0].to_world});
  nlohmann::json single =
      test::simulate(machine("depth_first", "auto"), instanced_scene(once), rays);
  EXPECT_EQ(single["bvh"]["levels"], 1);
}

// Intel's records (xe6 nodes, xe_quad leaves, 128-byte instance leaves read 64 bytes at a time)
// through the timing model: every ray as Embree answers it, and the bvh section names one node
// and one leaf block of each format.
TEST(SimInstancing, IntelXeRecordsGiveEmbreesAnswersOnTwoLevels) {
  Scene scene = instanced_scene(test::instanced_world());
  std::vector<Ray> rays = world_rays(2000, 9);
  HwConfig xe = machine("depth_first", "two_level");
  xe.bvh.node_format = NodeFormat::Xe6;
  xe.bvh.triangle_format = TriangleFormat::XeQuad;
  xe.bvh.width = 6;
  xe.bvh.max_leaf_size = 2;
  nlohmann::json doc = test::simulate(xe, scene, rays, true);
  EXPECT_EQ(doc["verify"]["rays"], rays.size());
  EXPECT_EQ(doc["verify"]["unexplained"], 0) << doc["verify"].dump();
  EXPECT_EQ(doc["bvh"]["node_bytes"], 64);
  EXPECT_EQ(doc["bvh"]["leaf_bytes"], 64);
  nlohmann::json flat = test::simulate(machine("depth_first", "flatten"), scene, rays);
  EXPECT_EQ(flat["bvh"]["node_bytes"], 256) << "aabb32 BVH8";
  EXPECT_EQ(flat["bvh"]["leaf_bytes"], 40) << "a raw triangle";
}

// The built-in forest gets two levels by itself (auto: its meshes are placed many times).
TEST(SimInstancing, TheForestRunsOnTwoLevelsInTreeletMode) {
  test::SimScene s("forest:200000");
  std::vector<Ray> rays = test::mixed_rays(s.scene, 1500, 4);
  nlohmann::json doc = test::simulate(machine("treelet", "auto"), s.scene, rays, true);
  EXPECT_EQ(doc["bvh"]["levels"], 2);
  EXPECT_EQ(doc["bvh"]["instances"], s.scene.instanced.instances.size());
  EXPECT_EQ(doc["verify"]["unexplained"], 0) << doc["verify"].dump();
  EXPECT_GT(test::stat(doc, "bvh.instances_per_ray"), 0.5);
}

TEST(SimInstancing, AFlatSceneOnTwoLevelsIsOneInstance) {
  test::SimScene s("grid:64");
  std::vector<Ray> rays = test::mixed_rays(s.scene, 1000, 2);
  nlohmann::json doc = test::simulate(machine("treelet", "two_level"), s.scene, rays, true);
  EXPECT_EQ(doc["bvh"]["levels"], 2);
  EXPECT_EQ(doc["bvh"]["instances"], 1);
  EXPECT_EQ(doc["verify"]["unexplained"], 0);
  double entered = test::stat(doc, "bvh.instances_per_ray");
  EXPECT_LE(entered, 1.0) << "a ray enters the one instance at most once";
  EXPECT_GT(entered, 0.5) << "rays that meet the scene's box enter it";
}

// stats.json's bvh section names the bytes of one node and one leaf record of each level: rtsim's
// aabb32 and raw records on one level, AMD's radv records (amd_nodes.h) on two, where the timed
// run also finds Embree's answers.
TEST(SimInstancing, TheBvhSectionGivesNodeAndLeafBytes) {
  Scene scene = instanced_scene(test::instanced_world());
  std::vector<Ray> rays = world_rays(1500, 6);
  nlohmann::json flat = test::simulate(machine("depth_first", "flatten"), scene, rays);
  EXPECT_EQ(flat["bvh"]["node_bytes"], 256) << "bvh8 aabb32";
  EXPECT_EQ(flat["bvh"]["leaf_bytes"], 40) << "raw triangle";
  HwConfig amd =
      load_hw_config("", {"bvh.instancing=\"two_level\"", "bvh.node_format=\"amd_box16\"",
                          "bvh.width=4", "bvh.max_leaf_size=1", "bvh.triangle_format=\"amd_tri\""});
  nlohmann::json two = test::simulate(amd, scene, rays, true);
  EXPECT_EQ(two["verify"]["unexplained"], 0) << two["verify"].dump();
  EXPECT_EQ(two["bvh"]["node_bytes"], 64) << "radv_bvh_box16_node";
  EXPECT_EQ(two["bvh"]["leaf_bytes"], 64) << "radv_bvh_triangle_node";
  EXPECT_EQ(two["bvh"]["top"]["node_bytes"], 64);
  EXPECT_EQ(two["bvh"]["top"]["leaf_bytes"], 128) << "radv_bvh_instance_node";
}

}  // namespace
}  // namespace rtsim
