#include "model/units/prepared_ray.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rtsim {
namespace {

// A direction whose largest component lies outside [2^-32, 2^32] is rescaled by a power of two
// (exact), so reciprocals and shear constants stay finite for denormal directions.
int direction_exponent(const glm::vec3& dir) {
  float largest = std::max({std::fabs(dir.x), std::fabs(dir.y), std::fabs(dir.z)});
  if (largest >= 0x1p-32f && largest <= 0x1p32f) return 0;
  return std::ilogb(largest);
}

}  // namespace

PreparedRay prepare_ray(const Ray& ray, float scene_extent, float box_padding) {
  PreparedRay r;
  int e = direction_exponent(ray.dir);
  r.org = ray.org;
  r.dir = ray.dir;
  r.tmin = ray.tmin;
  r.tmax = ray.tmax;
  if (e != 0) {
    r.dir =
        glm::vec3(std::ldexp(ray.dir.x, -e), std::ldexp(ray.dir.y, -e), std::ldexp(ray.dir.z, -e));
    r.t_exponent = -e;
    r.tmin = std::ldexp(ray.tmin, e);
    r.tmax = std::ldexp(ray.tmax, e);
    r.t_limit = std::ldexp(std::numeric_limits<float>::max(), e);
  }

  // Box setup: reciprocal (+-inf for a +-0 component), near plane by the sign bit, and the
  // origin moved by the padding so that each box is tested grown on every side.
  float pad =
      box_padding *
      (std::max({std::fabs(r.org.x), std::fabs(r.org.y), std::fabs(r.org.z)}) + scene_extent);
  for (int a = 0; a < 3; ++a) {
    r.inv_dir[a] = 1.0f / r.dir[a];
    r.near_is_hi[a] = std::signbit(r.dir[a]) ? 1 : 0;
    float toward = r.near_is_hi[a] ? -pad : pad;
    r.org_near[a] = r.org[a] + toward;
    r.org_far[a] = r.org[a] - toward;
  }

  // Triangle setup: z is the largest direction axis; swapping x and y keeps the winding.
  glm::vec3 mag(std::fabs(r.dir.x), std::fabs(r.dir.y), std::fabs(r.dir.z));
  r.kz = mag.x > mag.y ? (mag.x > mag.z ? 0 : 2) : (mag.y > mag.z ? 1 : 2);
  r.kx = (r.kz + 1) % 3;
  r.ky = (r.kx + 1) % 3;
  if (r.dir[r.kz] < 0.0f) std::swap(r.kx, r.ky);
  r.sx = r.dir[r.kx] / r.dir[r.kz];
  r.sy = r.dir[r.ky] / r.dir[r.kz];
  r.sz = 1.0f / r.dir[r.kz];
  return r;
}

}  // namespace rtsim
