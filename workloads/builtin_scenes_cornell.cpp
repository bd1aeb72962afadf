// The Cornell box as measured at Cornell (graphics.cornell.edu/online/box/data.html), in
// millimetres: five walls, the short and the tall block (five faces each, no bottoms) and the
// ceiling light. 32 triangles. Camera of the original: (278, 273, -800) looking along +z.
#include "workloads/builtin_scenes.h"

namespace rtsim::builtin {
namespace {

using V = glm::vec3;

// The light is lowered 0.1 mm below the measured 548.8 so it is not coplanar with the ceiling.
constexpr float kLightY = 548.7f;

void add_block(SceneBuilder& b, const V (&faces)[5][4], uint32_t mat, uint32_t obj) {
  for (const auto& f : faces) b.quad(f[0], f[1], f[2], f[3], mat, obj);
}

}  // namespace

Scene make_cornell() {
  SceneBuilder b("builtin:cornell");
  Material white = make_material("white", V(0.725f, 0.71f, 0.68f), 1.0f);
  Material red = make_material("red", V(0.63f, 0.065f, 0.05f), 1.0f);
  Material green = make_material("green", V(0.14f, 0.45f, 0.091f), 1.0f);
  Material light = make_material("light", V(0.78f), 1.0f);
  light.emission = V(17.0f, 12.0f, 4.0f);
  uint32_t m_white = b.material(white), m_red = b.material(red), m_green = b.material(green);
  uint32_t m_light = b.material(light);

  b.quad(V(552.8f, 0, 0), V(0, 0, 0), V(0, 0, 559.2f), V(549.6f, 0, 559.2f), m_white,
         b.object("floor"));
  b.quad(V(556.0f, 548.8f, 0), V(556.0f, 548.8f, 559.2f), V(0, 548.8f, 559.2f), V(0, 548.8f, 0),
         m_white, b.object("ceiling"));
  b.quad(V(549.6f, 0, 559.2f), V(0, 0, 559.2f), V(0, 548.8f, 559.2f), V(556.0f, 548.8f, 559.2f),
         m_white, b.object("back_wall"));
  b.quad(V(0, 0, 559.2f), V(0, 0, 0), V(0, 548.8f, 0), V(0, 548.8f, 559.2f), m_green,
         b.object("right_wall"));
  b.quad(V(552.8f, 0, 0), V(549.6f, 0, 559.2f), V(556.0f, 548.8f, 559.2f), V(556.0f, 548.8f, 0),
         m_red, b.object("left_wall"));

  const V short_block[5][4] = {
      {V(130, 165, 65), V(82, 165, 225), V(240, 165, 272), V(290, 165, 114)},
      {V(290, 0, 114), V(290, 165, 114), V(240, 165, 272), V(240, 0, 272)},
      {V(130, 0, 65), V(130, 165, 65), V(290, 165, 114), V(290, 0, 114)},
      {V(82, 0, 225), V(82, 165, 225), V(130, 165, 65), V(130, 0, 65)},
      {V(240, 0, 272), V(240, 165, 272), V(82, 165, 225), V(82, 0, 225)}};
  add_block(b, short_block, m_white, b.object("short_block"));
  const V tall_block[5][4] = {
      {V(423, 330, 247), V(265, 330, 296), V(314, 330, 456), V(472, 330, 406)},
      {V(423, 0, 247), V(423, 330, 247), V(472, 330, 406), V(472, 0, 406)},
      {V(472, 0, 406), V(472, 330, 406), V(314, 330, 456), V(314, 0, 456)},
      {V(314, 0, 456), V(314, 330, 456), V(265, 330, 296), V(265, 0, 296)},
      {V(265, 0, 296), V(265, 330, 296), V(423, 330, 247), V(423, 0, 247)}};
  add_block(b, tall_block, m_white, b.object("tall_block"));

  b.quad(V(343, kLightY, 227), V(343, kLightY, 332), V(213, kLightY, 332), V(213, kLightY, 227),
         m_light, b.object("light"));
  return std::move(b.scene());
}

}  // namespace rtsim::builtin
