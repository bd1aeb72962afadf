#include "workloads/hardcases.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/vec2.hpp>
#include <limits>
#include <map>

namespace rtsim::hardcases {
namespace {

// SplitMix64 and exact 24-bit uniforms: bit-identical everywhere.
struct Random {
  uint64_t state;
  uint64_t next() {
    uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  float uniform() { return static_cast<float>(next() >> 40) * 0x1p-24f; }
  float range(float lo, float hi) { return lo + (hi - lo) * uniform(); }
  // Uniform in the unit ball, by rejection.
  glm::vec3 in_ball() {
    for (;;) {
      glm::vec3 p(range(-1, 1), range(-1, 1), range(-1, 1));
      float n2 = p.x * p.x + p.y * p.y + p.z * p.z;
      if (n2 <= 1.0f && n2 > 1e-6f) return p;
    }
  }
  glm::vec3 direction() {
    glm::vec3 p = in_ball();
    return p / std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
  }
};

// 4 * quarter points on the unit circle, counter-clockwise from (1, 0), from the rational
// parametrization ((1 - t^2) / (1 + t^2), 2t / (1 + t^2)) and exact quarter turns.
std::vector<glm::vec2> circle(int quarter) {
  std::vector<glm::vec2> q1;
  for (int k = 0; k < quarter; ++k) {
    float t = float(k) / float(quarter);
    q1.push_back({(1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)});
  }
  std::vector<glm::vec2> out;
  for (int turn = 0; turn < 4; ++turn)
    for (glm::vec2 p : q1) {
      for (int i = 0; i < turn; ++i) p = {-p.y, p.x};
      out.push_back(p);
    }
  return out;
}

uint32_t add_vertex(TriangleMesh& m, const glm::vec3& p) {
  m.positions.push_back(p);
  return static_cast<uint32_t>(m.positions.size() - 1);
}

void append(TriangleMesh& into, const TriangleMesh& part) {
  uint32_t base = static_cast<uint32_t>(into.positions.size());
  into.positions.insert(into.positions.end(), part.positions.begin(), part.positions.end());
  for (auto tri : part.triangles)
    into.triangles.push_back({tri[0] + base, tri[1] + base, tri[2] + base});
}

Ray make_ray(const glm::vec3& org, const glm::vec3& dir, RayType type = RayType::Camera) {
  Ray ray;
  ray.org = org;
  ray.dir = dir;
  ray.type = type;
  return ray;
}

// Fan of 4 * quarter triangles around `center` in the plane z = center.z.
TriangleMesh fan(const glm::vec3& center, float radius, int quarter) {
  TriangleMesh m;
  uint32_t hub = add_vertex(m, center);
  auto rim = circle(quarter);
  for (const glm::vec2& p : rim) add_vertex(m, center + radius * glm::vec3(p.x, p.y, 0));
  uint32_t n = static_cast<uint32_t>(rim.size());
  for (uint32_t i = 0; i < n; ++i) m.triangles.push_back({hub, 1 + i, 1 + (i + 1) % n});
  return m;
}

// cells x cells unit squares in the plane z = corner.z, diagonals alternating.
TriangleMesh grid(const glm::vec3& corner, int cells) {
  TriangleMesh m;
  for (int y = 0; y <= cells; ++y)
    for (int x = 0; x <= cells; ++x) add_vertex(m, corner + glm::vec3(float(x), float(y), 0));
  auto at = [&](int x, int y) { return uint32_t(y * (cells + 1) + x); };
  for (int y = 0; y < cells; ++y)
    for (int x = 0; x < cells; ++x) {
      uint32_t a = at(x, y), b = at(x + 1, y), c = at(x + 1, y + 1), d = at(x, y + 1);
      if ((x + y) % 2) {
        m.triangles.push_back({a, b, c});
        m.triangles.push_back({a, c, d});
      } else {
        m.triangles.push_back({a, b, d});
        m.triangles.push_back({b, c, d});
      }
    }
  return m;
}

// Cube [-1, 1]^3 with each face split into 2 x 2 squares; vertices shared between faces.
TriangleMesh split_cube(const glm::vec3& center) {
  TriangleMesh m;
  std::map<std::array<int, 3>, uint32_t> index;
  auto vertex = [&](std::array<int, 3> p) {
    auto [it, fresh] = index.try_emplace(p, uint32_t(m.positions.size()));
    if (fresh) m.positions.push_back(center + glm::vec3(float(p[0]), float(p[1]), float(p[2])));
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side : {-1, 1})
      for (int i = -1; i < 1; ++i)
        for (int j = -1; j < 1; ++j) {
          auto corner = [&](int di, int dj) {
            std::array<int, 3> p{};
            p[axis] = side;
            p[(axis + 1) % 3] = i + di;
            p[(axis + 2) % 3] = j + dj;
            return vertex(p);
          };
          uint32_t a = corner(0, 0), b = corner(1, 0), c = corner(1, 1), d = corner(0, 1);
          m.triangles.push_back({a, b, c});
          m.triangles.push_back({a, c, d});
        }
  return m;
}

// A quad with corners a, b, c, d (two triangles).
TriangleMesh quad(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d) {
  TriangleMesh m;
  m.positions = {a, b, c, d};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

}  // namespace

TriangleMesh closed_sphere(const glm::vec3& center, float radius, int segments) {
  int quarter = std::max(1, segments / 4);
  auto around = circle(quarter);
  // Latitudes from the south pole up: the circle's fourth quadrant, then its first.
  std::vector<glm::vec2> lat;
  for (int k = 0; k < quarter; ++k) lat.push_back(around[3 * quarter + k]);
  for (int k = 0; k < quarter; ++k) lat.push_back(around[k]);
  TriangleMesh m;
  uint32_t south = add_vertex(m, center + glm::vec3(0, -radius, 0));
  uint32_t n = static_cast<uint32_t>(around.size());
  // Rings (skip index 0: the south pole itself).
  for (size_t r = 1; r < lat.size(); ++r)
    for (const glm::vec2& p : around)
      add_vertex(m, center + radius * glm::vec3(lat[r].x * p.x, lat[r].y, lat[r].x * p.y));
  uint32_t north = add_vertex(m, center + glm::vec3(0, radius, 0));
  uint32_t rings = static_cast<uint32_t>(lat.size() - 1);
  auto at = [&](uint32_t ring, uint32_t i) { return 1 + ring * n + i % n; };
  for (uint32_t i = 0; i < n; ++i) {
    m.triangles.push_back({south, at(0, i + 1), at(0, i)});
    m.triangles.push_back({north, at(rings - 1, i), at(rings - 1, i + 1)});
    for (uint32_t r = 0; r + 1 < rings; ++r) {
      m.triangles.push_back({at(r, i), at(r, i + 1), at(r + 1, i + 1)});
      m.triangles.push_back({at(r, i), at(r + 1, i + 1), at(r + 1, i)});
    }
  }
  return m;
}

TriangleMesh closed_torus(const glm::vec3& center, float major_radius, float minor_radius,
                          int major_segments, int minor_segments) {
  auto major = circle(std::max(1, major_segments / 4));
  auto minor = circle(std::max(1, minor_segments / 4));
  uint32_t nu = static_cast<uint32_t>(major.size()), nv = static_cast<uint32_t>(minor.size());
  TriangleMesh m;
  for (const glm::vec2& u : major)
    for (const glm::vec2& v : minor) {
      float ring = major_radius + minor_radius * v.x;
      add_vertex(m, center + glm::vec3(ring * u.x, minor_radius * v.y, ring * u.y));
    }
  auto at = [&](uint32_t i, uint32_t j) { return (i % nu) * nv + j % nv; };
  for (uint32_t i = 0; i < nu; ++i)
    for (uint32_t j = 0; j < nv; ++j) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

std::vector<Ray> rays_from_inside_sphere(const glm::vec3& center, float spread, size_t count,
                                         uint64_t seed) {
  Random random{seed};
  std::vector<Ray> rays;
  rays.reserve(count);
  for (size_t i = 0; i < count; ++i)
    rays.push_back(make_ray(center + spread * random.in_ball(), random.direction()));
  return rays;
}

std::vector<Ray> rays_from_inside_torus(const glm::vec3& center, float major_radius, float spread,
                                        size_t count, uint64_t seed) {
  Random random{seed};
  std::vector<Ray> rays;
  rays.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    // A point of the center circle: rational parameter, random quarter turn.
    float t = random.uniform();
    glm::vec2 p((1 - t * t) / (1 + t * t), 2 * t / (1 + t * t));
    for (uint64_t turn = random.next() % 4; turn > 0; --turn) p = {-p.y, p.x};
    glm::vec3 on_circle = center + major_radius * glm::vec3(p.x, 0, p.y);
    rays.push_back(make_ray(on_circle + spread * random.in_ball(), random.direction()));
  }
  return rays;
}

std::vector<HardCase> make_hard_cases(size_t n, uint64_t seed) {
  std::vector<HardCase> cases;
  Random random{seed};
  auto add = [&](std::string name, std::string what, TriangleMesh mesh, Expect expect) {
    cases.push_back({std::move(name), std::move(what), std::move(mesh), {}, expect});
    return &cases.back();
  };
  // Origins above or below a plane z = plane_z, never grazing.
  auto off_plane = [&](const glm::vec3& target, float plane_z) {
    glm::vec3 d = random.direction();
    if (std::fabs(d.z) < 0.2f) d.z = d.z < 0 ? -0.2f : 0.2f;
    return glm::vec3(target.x, target.y, plane_z) + random.range(0.5f, 3.0f) * d;
  };

  HardCase* c = add("fan_vertex", "rays aimed exactly at the hub shared by 16 triangles",
                    fan({0, 0, 0}, 1.0f, 4), Expect::AllHit);
  for (size_t i = 0; i < n; ++i) {
    glm::vec3 o = off_plane({0, 0, 0}, 0.0f);
    c->rays.push_back(make_ray(o, -o));
  }
  c = add("fan_edges", "rays aimed at points of the spokes shared by two triangles",
          fan({0, 0, 0}, 1.0f, 4), Expect::AllHit);
  for (size_t i = 0; i < n; ++i) {
    const glm::vec3& rim = c->mesh.positions[1 + random.next() % 16];
    glm::vec3 target = random.range(0.05f, 0.95f) * rim;
    glm::vec3 o = off_plane(target, 0.0f);
    c->rays.push_back(make_ray(o, target - o));
  }
  c = add("grid_vertices", "rays aimed at interior vertices and edge midpoints of a grid",
          grid({0, 0, 0}, 8), Expect::AllHit);
  for (size_t i = 0; i < n; ++i) {
    glm::vec3 target(float(1 + random.next() % 13) * 0.5f + 0.5f,
                     float(1 + random.next() % 13) * 0.5f + 0.5f, 0.0f);
    glm::vec3 o = off_plane(target, 0.0f);
    c->rays.push_back(make_ray(o, target - o));
  }
  c = add("sphere_inside", "rays from inside a closed sphere, also through every vertex",
          closed_sphere({0, 0, 0}, 1.0f, 48), Expect::AllHit);
  for (const glm::vec3& v : c->mesh.positions) c->rays.push_back(make_ray({0, 0, 0}, v));
  for (const Ray& r : rays_from_inside_sphere({0, 0, 0}, 0.8f, n, random.next()))
    c->rays.push_back(r);
  c = add("torus_inside", "rays from inside the tube of a closed torus",
          closed_torus({0, 0, 0}, 2.0f, 0.5f, 48, 24), Expect::AllHit);
  c->rays = rays_from_inside_torus({0, 0, 0}, 2.0f, 0.3f, n, random.next());
  c = add("grazing", "rays in and nearly in the plane of a grid", grid({0, 0, 0}, 8),
          Expect::MatchEmbree);
  for (size_t i = 0; i < n; ++i) {
    glm::vec3 o(random.range(-2, 10), random.range(-2, 10), 0.0f);
    glm::vec3 d = random.direction();
    float dz[] = {0.0f, -0.0f, 1e-7f, -1e-7f, 1e-30f};
    d.z = dz[random.next() % 5];
    c->rays.push_back(make_ray(o, d));
  }
  c = add("axis_zero", "axis-aligned rays with +0/-0 components from inside a split cube",
          split_cube({0, 0, 0}), Expect::AllHit);
  for (float x : {-0.5f, 0.0f, 0.5f})
    for (float y : {-0.5f, 0.0f, 0.5f})
      for (float z : {-0.5f, 0.0f, 0.5f})
        for (int axis = 0; axis < 3; ++axis)
          for (float sign : {1.0f, -1.0f})
            for (int zeros = 0; zeros < 4; ++zeros) {
              glm::vec3 d;
              d[(axis + 1) % 3] = (zeros & 1) ? -0.0f : 0.0f;
              d[(axis + 2) % 3] = (zeros & 2) ? -0.0f : 0.0f;
              d[axis] = sign;
              c->rays.push_back(make_ray({x, y, z}, d));
            }
  c = add("on_surface", "rays starting on the triangles of a sphere, both ways",
          closed_sphere({0, 0, 0}, 1.0f, 32), Expect::MatchEmbree);
  for (size_t i = 0; i < n; ++i) {
    const auto& tri = c->mesh.triangles[random.next() % c->mesh.triangle_count()];
    float s = random.uniform(), t = random.uniform() * (1 - s);
    glm::vec3 a = c->mesh.positions[tri[0]], b = c->mesh.positions[tri[1]],
              d = c->mesh.positions[tri[2]];
    c->rays.push_back(make_ray(a + s * (b - a) + t * (d - a), random.direction()));
  }
  c = add("offset_1e5", "closed sphere of radius 10 at 1e5 from the origin",
          closed_sphere({1e5f, 1e5f, -1e5f}, 10.0f, 48), Expect::AllHit);
  c->rays = rays_from_inside_sphere({1e5f, 1e5f, -1e5f}, 7.0f, n, random.next());
  c = add("offset_1e7", "closed sphere of radius 1000 at 1e7 from the origin",
          closed_sphere({1e7f, -1e7f, 1e7f}, 1000.0f, 48), Expect::AllHit);
  c->rays = rays_from_inside_sphere({1e7f, -1e7f, 1e7f}, 700.0f, n, random.next());
  c = add("tiny", "closed sphere of 1e-6 triangles at (1, 2, 3)",
          closed_sphere({1, 2, 3}, 4e-6f, 24), Expect::AllHit);
  c->rays = rays_from_inside_sphere({1, 2, 3}, 1e-6f, n, random.next());
  c = add("huge", "closed sphere of 1e6 triangles", closed_sphere({0, 0, 0}, 4e6f, 24),
          Expect::AllHit);
  c->rays = rays_from_inside_sphere({0, 0, 0}, 2e6f, n, random.next());

  TriangleMesh odd = quad({-5, -5, -1}, {5, -5, -1}, {5, 5, -1}, {-5, 5, -1});
  TriangleMesh needles;
  needles.positions = {{0, 0, 0},   {1, 0, 0},  {2, 0, 0},          {0, 1, 0},
                       {1, 2, 0},   {0, 3, 0},  {4, 3, 0},          {0, 3.000001f, 0},
                       {-3, -3, 0}, {3, -3, 0}, {0, -3.0000001f, 0}};
  needles.triangles = {{0, 1, 2}, {3, 3, 4}, {5, 6, 7}, {8, 9, 10}, {1, 1, 1}};
  append(odd, needles);
  c = add("needles_degenerate", "zero-area, repeated-vertex and needle triangles over a wall", odd,
          Expect::MatchEmbree);
  for (size_t i = 0; i < n; ++i) {
    glm::vec3 target(random.range(-4, 4), random.range(-4, 4), 0.0f);
    glm::vec3 o = off_plane(target, 0.0f);
    if (o.z < 0) o.z = -o.z;
    c->rays.push_back(make_ray(o, target - o));
  }
  c = add("tmax", "tmax exactly at, just before and beyond a plane, and +inf", grid({0, 0, 0}, 8),
          Expect::MatchEmbree);
  for (size_t i = 0; i < n; ++i) {
    Ray r = make_ray({random.range(0.5f, 7.5f), random.range(0.5f, 7.5f), random.range(1, 3)},
                     {0, 0, -1}, RayType::Shadow);
    float tmax[] = {r.org.z, std::nextafter(r.org.z, 0.0f), 2 * r.org.z,
                    std::numeric_limits<float>::infinity()};
    r.tmax = tmax[i % 4];
    r.query = i % 8 < 4 ? Query::AnyHit : Query::ClosestHit;
    c->rays.push_back(r);
  }
  c = add("denormal_dir", "directions with denormal components, and wholly denormal ones",
          quad({10, -10, -10}, {10, 10, -10}, {10, 10, 10}, {10, -10, 10}), Expect::AllHit);
  float tiny[] = {1e-40f, -1e-40f, 1e-45f, -1e-45f, 0.0f, -0.0f, 1e-38f};
  for (size_t i = 0; i < n; ++i) {
    glm::vec3 o(random.range(-5, 5), random.range(-5, 5), random.range(-5, 5));
    glm::vec3 d(1.0f, tiny[random.next() % 7], tiny[random.next() % 7]);
    if (i % 4 == 0) {
      o.x = 9.999f;
      d.x = 1e-39f;
    }
    c->rays.push_back(make_ray(o, d));
  }
  return cases;
}

Scene make_hardcases_scene() {
  Scene scene;
  scene.source = "builtin:hardcases";
  Material material;
  material.name = "hardcase";
  scene.materials.push_back(material);
  // One material; one object per case.
  for (const HardCase& c : make_hard_cases(0)) {
    uint32_t object = static_cast<uint32_t>(scene.object_names.size());
    scene.object_names.push_back(c.name);
    append(scene.mesh, c.mesh);
    scene.material_ids.resize(scene.mesh.triangle_count(), 0);
    scene.object_ids.resize(scene.mesh.triangle_count(), object);
  }
  return scene;
}

}  // namespace rtsim::hardcases
