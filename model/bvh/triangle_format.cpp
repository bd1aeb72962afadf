#include "model/bvh/triangle_format.h"

#include "model/bvh/amd_nodes.h"
#include "model/bvh/intel_nodes.h"
#include "traces/alpha.h"

#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace rtsim {
namespace {

// Rows of the world-to-unit-triangle map: u = row0 . (p, 1), v = row1 . (p, 1), and the plane
// distance z = row2 . (p, 1). Computed in double; zero rows for a degenerate triangle.
void woop_rows(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, float out[12]) {
  glm::dvec3 e1 = b - a, e2 = c - a, n = glm::cross(e1, e2);
  std::memset(out, 0, 12 * sizeof(float));
  glm::dmat3 to_world(e1, e2, n);
  double det = glm::determinant(to_world);
  if (det == 0.0 || !std::isfinite(det)) return;
  glm::dmat3 to_local = glm::inverse(to_world);
  for (int row = 0; row < 3; ++row) {
    glm::dvec3 r(to_local[0][row], to_local[1][row], to_local[2][row]);
    out[4 * row + 0] = static_cast<float>(r.x);
    out[4 * row + 1] = static_cast<float>(r.y);
    out[4 * row + 2] = static_cast<float>(r.z);
    out[4 * row + 3] = static_cast<float>(-glm::dot(r, a));
  }
}

}  // namespace

uint32_t triangle_stride(TriangleFormat format) {
  switch (format) {
    case TriangleFormat::Woop: return kWoopTriangleBytes;
    case TriangleFormat::AmdTriangle: return kAmdTriangleBytes;
    case TriangleFormat::XeQuad: return kXeQuadBytes;
    default: return kRawTriangleBytes;
  }
}

void encode_triangle(TriangleFormat format, const TriangleMesh& mesh, uint32_t prim, uint8_t* out) {
  glm::vec3 v[3] = {mesh.vertex(prim, 0), mesh.vertex(prim, 1), mesh.vertex(prim, 2)};
  if (format == TriangleFormat::AmdTriangle) {
    bool opaque = !mesh.alpha || !mesh.alpha->tested(prim);
    encode_amd_triangle(&v[0].x, prim, opaque, out);
    return;
  }
  if (format == TriangleFormat::XeQuad) {
    encode_xe_quad(mesh, prim, nullptr, out);
    return;
  }
  if (format == TriangleFormat::Raw) {
    std::memcpy(out, v, 36);
    std::memcpy(out + 36, &prim, 4);
    return;
  }
  float rows[12];
  woop_rows(glm::dvec3(v[0]), glm::dvec3(v[1]), glm::dvec3(v[2]), rows);
  std::memcpy(out, rows, 48);
  std::memcpy(out + 48, &prim, 4);
}

}  // namespace rtsim
