// Numerical hard cases for ray traversal: closed meshes, fans and grids with rays aimed exactly
// at shared edges and vertices, grazing and axis-aligned (+-0) rays, rays starting on a surface,
// geometry offset to 1e5 and 1e7, tiny (1e-6) and huge (1e6) triangles, needles and zero-area
// triangles, finite and infinite tmax, denormal directions. Each case is geometry + rays + what
// a correct traversal must do; `make_hardcases_scene` puts all the geometry in one built-in
// scene ("hardcases"). Built from +, *, / only (rational circle points, seeded integer
// randomness), so every machine gets bit-identical meshes and rays.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "traces/ray.h"
#include "workloads/scene.h"

namespace rtsim::hardcases {

enum class Expect : uint8_t {
  AllHit,       // every ray must hit (watertightness)
  MatchEmbree,  // only agreement with Embree up to explained classes is required
};

struct HardCase {
  std::string name;
  std::string what;  // one line: what the case probes
  TriangleMesh mesh;
  std::vector<Ray> rays;
  Expect expect = Expect::MatchEmbree;
};

// Closed (watertight, shared vertices) UV sphere: `segments` around, segments / 2 rings.
TriangleMesh closed_sphere(const glm::vec3& center, float radius, int segments);
// Closed torus in the xz plane.
TriangleMesh closed_torus(const glm::vec3& center, float major_radius, float minor_radius,
                          int major_segments, int minor_segments);
// Rays with seeded uniform directions from seeded points within `spread` of the center.
std::vector<Ray> rays_from_inside_sphere(const glm::vec3& center, float spread, size_t count,
                                         uint64_t seed);
// Rays from seeded points inside the tube of the torus (within `spread` of its center circle).
std::vector<Ray> rays_from_inside_torus(const glm::vec3& center, float major_radius, float spread,
                                        size_t count, uint64_t seed);

// All cases; rays_per_case sizes the seeded random parts.
std::vector<HardCase> make_hard_cases(size_t rays_per_case = 2000, uint64_t seed = 1);

// The built-in scene "hardcases": every case's geometry, one object per case.
Scene make_hardcases_scene();

}  // namespace rtsim::hardcases
