// The geometry kit of the built-in scenes: template meshes (octahedron sphere, cube, grid quad)
// and a builder that instances them into a Scene with material and object ids.
#include <cmath>
#include <map>

#include "workloads/builtin_scenes.h"

namespace rtsim::builtin {

MeshTemplate octa_sphere(int level) {
  // Lattice points (x, y, z) with |x| + |y| + |z| = level lie on the octahedron; a point shared
  // by two faces gets one index, so the sphere is watertight.
  MeshTemplate t;
  std::map<std::array<int, 3>, uint32_t> index_of;
  auto vertex = [&](int x, int y, int z) {
    auto [it, inserted] = index_of.try_emplace({x, y, z}, uint32_t(t.positions.size()));
    if (inserted) {
      glm::vec3 p{float(x), float(y), float(z)};
      t.positions.push_back(p / std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z));
    }
    return it->second;
  };
  for (int octant = 0; octant < 8; ++octant) {
    int sx = octant & 1 ? -1 : 1, sy = octant & 2 ? -1 : 1, sz = octant & 4 ? -1 : 1;
    bool flip = sx * sy * sz < 0;
    auto at = [&](int a, int b) { return vertex(sx * a, sy * b, sz * (level - a - b)); };
    // Corners numbered last to first: the order GCC's right-to-left argument evaluation gave
    // the pinned fingerprints, spelled out so that every compiler agrees.
    auto emit = [&](std::array<int, 2> p, std::array<int, 2> q, std::array<int, 2> r) {
      uint32_t k = at(r[0], r[1]), j = at(q[0], q[1]), i = at(p[0], p[1]);
      t.triangles.push_back(flip ? std::array<uint32_t, 3>{i, k, j}
                                 : std::array<uint32_t, 3>{i, j, k});
    };
    for (int a = 0; a < level; ++a) {
      for (int b = 0; a + b < level; ++b) {
        emit({a, b}, {a + 1, b}, {a, b + 1});
        if (a + b + 1 < level) emit({a + 1, b}, {a + 1, b + 1}, {a, b + 1});
      }
    }
  }
  return t;
}

MeshTemplate unit_cube() {
  MeshTemplate t;
  for (int i = 0; i < 8; ++i)
    t.positions.emplace_back(i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 1.0f : -1.0f);
  const uint32_t faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& f : faces) {
    t.triangles.push_back({f[0], f[1], f[2]});
    t.triangles.push_back({f[0], f[2], f[3]});
  }
  return t;
}

MeshTemplate grid_quad(int cells) {
  MeshTemplate t;
  auto coord = [cells](int i) { return float(2 * i - cells) / float(cells); };
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) t.positions.emplace_back(coord(i), 0.0f, coord(j));
  auto at = [cells](int i, int j) { return uint32_t(j * (cells + 1) + i); };
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      t.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
      t.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
    }
  }
  return t;
}

glm::mat3 rotation_y(float c, float s) {
  // glm is column-major: columns are the images of the x, y and z axes.
  return glm::mat3(glm::vec3(c, 0.0f, -s), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(s, 0.0f, c));
}

Material make_material(const std::string& name, const glm::vec3& color, float roughness) {
  Material m;
  m.name = name;
  m.base_color = color;
  m.roughness = roughness;
  return m;
}

SceneBuilder::SceneBuilder(std::string source) {
  scene_.source = std::move(source);
}

uint32_t SceneBuilder::material(const Material& m) {
  scene_.materials.push_back(m);
  return uint32_t(scene_.materials.size() - 1);
}

uint32_t SceneBuilder::object(const std::string& name) {
  scene_.object_names.push_back(name);
  return uint32_t(scene_.object_names.size() - 1);
}

void SceneBuilder::add(const MeshTemplate& t, const glm::vec3& offset, const glm::vec3& scale,
                       uint32_t material_id, uint32_t object_id, const glm::mat3& rotation) {
  auto base = uint32_t(scene_.mesh.positions.size());
  for (const auto& p : t.positions)
    scene_.mesh.positions.push_back(offset + rotation * (scale * p));
  for (const auto& tri : t.triangles)
    scene_.mesh.triangles.push_back({base + tri[0], base + tri[1], base + tri[2]});
  scene_.material_ids.insert(scene_.material_ids.end(), t.triangles.size(), material_id);
  scene_.object_ids.insert(scene_.object_ids.end(), t.triangles.size(), object_id);
}

void SceneBuilder::quad(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                        const glm::vec3& d, uint32_t material_id, uint32_t object_id) {
  MeshTemplate t{{a, b, c, d}, {{0, 1, 2}, {0, 2, 3}}, {}};
  add(t, glm::vec3(0.0f), glm::vec3(1.0f), material_id, object_id);
}

void SceneBuilder::reserve(size_t vertices, size_t triangles) {
  scene_.mesh.positions.reserve(vertices);
  scene_.mesh.triangles.reserve(triangles);
  scene_.material_ids.reserve(triangles);
  scene_.object_ids.reserve(triangles);
}

}  // namespace rtsim::builtin
