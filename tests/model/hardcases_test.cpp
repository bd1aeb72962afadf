// The numerical hard cases (workloads/hardcases.h) through every node format and width: rays
// that must hit do, and every disagreement with Embree is explained by the arbiter.
#include "workloads/hardcases.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <glm/geometric.hpp>

#include "model/verify/verifier.h"
#include "model_test_util.h"
#include "workloads/scene.h"

namespace rtsim {
namespace {

std::string describe_examples(const VerifyReport& r) {
  std::string out;
  char line[512];
  for (const Mismatch& m : r.unexplained_examples) {
    std::snprintf(
        line, sizeof line, "  %s: org %a %a %a dir %a %a %a tmax %a embree %u %a model %u %a\n",
        mismatch_class_name(m.verdict.cls), m.ray.org.x, m.ray.org.y, m.ray.org.z, m.ray.dir.x,
        m.ray.dir.y, m.ray.dir.z, m.ray.tmax, m.embree.prim, m.embree.t, m.model_prim, m.model.t);
    out += line;
  }
  return out;
}

class HardCases : public ::testing::TestWithParam<BvhConfig> {
 protected:
  static const std::vector<hardcases::HardCase>& cases() {
    static const auto all = hardcases::make_hard_cases(1000, 17);
    return all;
  }
};

TEST_P(HardCases, MustHitRaysHitAndNothingIsUnexplained) {
  for (const hardcases::HardCase& c : cases()) {
    BvhImage image = build_bvh_image(c.mesh, GetParam());
    TraversalUnit unit(image);
    EmbreeScene embree(c.mesh, 1);
    Verifier verifier(c.mesh, unit, embree, ArbiterConfig{}, 3);
    TraversalState state;
    size_t misses = 0;
    for (const Ray& ray : c.rays) {
      misses += !unit.trace(state, ray).hit();
      verifier.check(ray);
    }
    const VerifyReport& r = verifier.report();
    if (c.expect == hardcases::Expect::AllHit) {
      EXPECT_EQ(misses, 0u) << c.name << ": " << c.what << " / " << describe(GetParam());
    }
    EXPECT_EQ(r.unexplained(), 0u) << c.name << " / " << describe(GetParam()) << "\n"
                                   << describe_examples(r);
    EXPECT_EQ(r.rays, c.rays.size());
  }
}

TEST_P(HardCases, ZeroAreaTrianglesAreNeverHit) {
  for (const hardcases::HardCase& c : cases()) {
    if (c.name != "needles_degenerate") continue;
    BvhImage image = build_bvh_image(c.mesh, GetParam());
    TraversalUnit unit(image);
    TraversalState state;
    for (const Ray& ray : c.rays) {
      Hit hit = unit.trace(state, ray);
      if (!hit.hit()) continue;
      glm::vec3 a = c.mesh.vertex(hit.prim, 0), b = c.mesh.vertex(hit.prim, 1),
                d = c.mesh.vertex(hit.prim, 2);
      ASSERT_GT(glm::length(glm::cross(b - a, d - a)), 0.0f) << "hit triangle " << hit.prim;
    }
  }
}

std::vector<BvhConfig> hard_configs() {
  std::vector<BvhConfig> out = test::all_configs();
  BvhConfig bfs = test::config(NodeFormat::Cwbvh8, 8, 1);
  bfs.node_layout = NodeLayout::BreadthFirst;
  out.push_back(bfs);
  BvhConfig big_leaves = test::config(NodeFormat::Aabb32, 4, 8);
  big_leaves.sah_bins = 32;
  big_leaves.node_layout = NodeLayout::DepthFirst;
  out.push_back(big_leaves);
  return out;
}

std::string config_name(const ::testing::TestParamInfo<BvhConfig>& info) {
  const BvhConfig& c = info.param;
  return std::string(node_format_name(c.node_format)) + "_w" + std::to_string(c.width) + "_l" +
         std::to_string(c.max_leaf_size) + "_" + std::to_string(info.index);
}

INSTANTIATE_TEST_SUITE_P(AllFormats, HardCases, ::testing::ValuesIn(hard_configs()), config_name);

TEST(HardCasesScene, IsABuiltinScene) {
  Scene scene = load_scene("hardcases");
  EXPECT_EQ(scene.source, "builtin:hardcases");
  EXPECT_EQ(scene.object_names.size(), hardcases::make_hard_cases(0).size());
  EXPECT_EQ(scene.fingerprint, load_scene("builtin:hardcases").fingerprint);
  EXPECT_GT(scene.triangle_count(), 10000u);
}

TEST(HardCasesScene, CasesAreDeterministic) {
  auto a = hardcases::make_hard_cases(50, 3), b = hardcases::make_hard_cases(50, 3);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(mesh_fingerprint(a[i].mesh), mesh_fingerprint(b[i].mesh));
    ASSERT_EQ(a[i].rays.size(), b[i].rays.size());
    for (size_t r = 0; r < a[i].rays.size(); ++r) ASSERT_TRUE(a[i].rays[r] == b[i].rays[r]);
  }
}

}  // namespace
}  // namespace rtsim
