// Material assignment by object or material name pattern.
#include "workloads/pipeline/materials.h"

#include <gtest/gtest.h>

#include "tests/pipeline/test_scenes.h"

namespace rtsim::pipeline {
namespace {

TEST(Glob, StarsAndQuestionMarks) {
  EXPECT_TRUE(glob_match("*", ""));
  EXPECT_TRUE(glob_match("floor*", "floors"));
  EXPECT_TRUE(glob_match("*_floor_*", "arcs_floor_long"));
  EXPECT_TRUE(glob_match("obj?ct", "object"));
  EXPECT_FALSE(glob_match("floor", "floors"));
  EXPECT_FALSE(glob_match("?", ""));
  EXPECT_FALSE(glob_match("Floor*", "floors"));  // case-sensitive
}

TEST(Materials, RulesMatchObjectOrMaterialNamesAndLaterRulesWin) {
  Scene s;
  test::add_quad(s, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, test::material("stone", 0.9f),
                 "floor");
  test::add_quad(s, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, test::material("stone", 0.9f),
                 "wall");
  test::add_quad(s, {0, 0, 2}, {1, 0, 2}, {1, 1, 2}, {0, 1, 2}, test::material("glass", 0.0f),
                 "window");
  std::vector<MaterialRule> rules(3);
  rules[0].match = "*";
  rules[0].base_color = glm::vec3(0.5f);
  rules[1].match = "floor";
  rules[1].roughness = 0.2f;
  rules[2].match = "glass";  // a material name
  rules[2].transmission = 1.0f;
  rules[2].roughness = 0.05f;
  MaterialTable t = assign_materials(s, rules);
  ASSERT_EQ(t.of_triangle.size(), 6u);
  EXPECT_FLOAT_EQ(t.of(0).roughness, 0.2f);
  EXPECT_FLOAT_EQ(t.of(1).roughness, 0.2f);
  EXPECT_FLOAT_EQ(t.of(2).roughness, 0.9f);  // wall keeps the scene's value
  EXPECT_FLOAT_EQ(t.of(4).transmission, 1.0f);
  EXPECT_FLOAT_EQ(t.of(4).roughness, 0.05f);
  for (uint32_t tri = 0; tri < 6; ++tri) EXPECT_FLOAT_EQ(t.of(tri).base_color.x, 0.5f);
  EXPECT_EQ(t.materials.size(), 3u);  // one per (material, object) pair
}

TEST(Materials, GlossyMeansSharpBaseOrCoat) {
  ShadingMaterial m;
  m.roughness = 0.9f;
  EXPECT_FALSE(m.glossy(0.5f));
  m.layers = 2;
  m.coat_roughness = 0.05f;
  EXPECT_TRUE(m.glossy(0.5f));
  m.layers = 1;
  m.roughness = 0.5f;
  EXPECT_TRUE(m.glossy(0.5f));
}

}  // namespace
}  // namespace rtsim::pipeline
