#include "traces/instances.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/core.h>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "traces/hash.h"
#include "traces/instance_settings.h"

namespace rtsim {

Transform inverse(const Transform& t) {
  // In double, rounded once: the inverse of a well-conditioned fp32 matrix to fp32 accuracy.
  glm::dmat3 linear = glm::inverse(glm::dmat3(t.linear));
  Transform out;
  out.linear = glm::mat3(linear);
  out.offset = glm::vec3(-(linear * glm::dvec3(t.offset)));
  return out;
}

Bounds world_box(const Bounds& object, const Transform& to_world) {
  Bounds out;
  for (int corner = 0; corner < 8; ++corner)
    out.grow(to_world.point({corner & 1 ? object.hi.x : object.lo.x,
                             corner & 2 ? object.hi.y : object.lo.y,
                             corner & 4 ? object.hi.z : object.lo.z}));
  return out;
}

uint64_t InstancedMesh::unique_triangles() const {
  uint64_t n = 0;
  for (const TriangleMesh& m : meshes) n += m.triangle_count();
  return n;
}

uint64_t InstancedMesh::instanced_triangles() const {
  uint64_t n = 0;
  for (const Instance& i : instances)
    n += i.mesh < meshes.size() ? meshes[i.mesh].triangle_count() : 0;
  return n;
}

std::string instancing_problem(const InstancedMesh& g) {
  if (g.instances.empty()) return "no instances";
  for (size_t m = 0; m < g.meshes.size(); ++m)
    if (g.meshes[m].triangle_count() == 0) return fmt::format("mesh {} has no triangles", m);
  for (size_t i = 0; i < g.instances.size(); ++i) {
    const Instance& inst = g.instances[i];
    if (inst.mesh >= g.meshes.size())
      return fmt::format("instance {} names mesh {} of {}", i, inst.mesh, g.meshes.size());
    const Transform& t = inst.to_world;
    bool finite =
        std::isfinite(t.offset.x) && std::isfinite(t.offset.y) && std::isfinite(t.offset.z);
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) finite &= std::isfinite(t.linear[c][r]);
    if (!finite) return fmt::format("instance {} has a transform that is not finite", i);
    // Singular, or so skewed (|det| below 1e-6 of the columns' lengths' product) that an fp32
    // inverse and the boxes' padding would not hold: refused.
    glm::dmat3 linear(t.linear);
    double det = glm::determinant(linear);
    double scale = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
    if (!(std::fabs(det) > 1e-6 * scale) || scale == 0.0)
      return fmt::format("instance {} has a transform that is not invertible", i);
  }
  return "";
}

std::vector<uint64_t> flat_offsets(const InstancedMesh& g) {
  std::vector<uint64_t> out;
  uint64_t next = 0;
  for (const Instance& i : g.instances) {
    out.push_back(next);
    next += g.meshes[i.mesh].triangle_count();
  }
  return out;
}

FlatMesh flatten(const InstancedMesh& g) {
  FlatMesh out;
  out.flat_offsets = flat_offsets(g);
  size_t vertices = 0, triangles = 0;
  for (const Instance& i : g.instances) {
    vertices += g.meshes[i.mesh].positions.size();
    triangles += g.meshes[i.mesh].triangle_count();
  }
  out.mesh.positions.reserve(vertices);
  out.mesh.triangles.reserve(triangles);
  for (const Instance& i : g.instances) {
    const TriangleMesh& m = g.meshes[i.mesh];
    auto base = uint32_t(out.mesh.positions.size());
    for (const glm::vec3& p : m.positions) out.mesh.positions.push_back(i.to_world.point(p));
    for (const auto& tri : m.triangles)
      out.mesh.triangles.push_back({tri[0] + base, tri[1] + base, tri[2] + base});
  }
  bool any_alpha = false;
  for (const TriangleMesh& m : g.meshes) any_alpha |= m.alpha != nullptr;
  if (any_alpha) {
    auto alpha = std::make_shared<TriangleAlpha>();
    for (const Instance& i : g.instances)
      append_alpha(*alpha, g.meshes[i.mesh].alpha.get(), g.meshes[i.mesh].triangle_count());
    out.mesh.alpha = std::move(alpha);
  }
  return out;
}

uint64_t instanced_fingerprint(const InstancedMesh& g) {
  uint64_t n[2] = {g.meshes.size(), g.instances.size()};
  uint64_t h = fnv1a64(n, sizeof n);
  for (const TriangleMesh& m : g.meshes) {
    uint64_t mesh = mesh_fingerprint(m);
    h = fnv1a64(&mesh, sizeof mesh, h);
  }
  for (const Instance& i : g.instances) {
    h = fnv1a64(&i.mesh, sizeof i.mesh, h);
    h = fnv1a64(&i.to_world.linear, sizeof i.to_world.linear, h);
    h = fnv1a64(&i.to_world.offset, sizeof i.to_world.offset, h);
  }
  return h;
}

FlatTriangles::FlatTriangles(const TriangleMesh& flat)
    : flat_(&flat), count_(flat.triangle_count()) {}

FlatTriangles::FlatTriangles(const InstancedMesh& geometry, const InstanceSettings* settings)
    : instances_(&geometry),
      settings_(settings),
      offsets_(flat_offsets(geometry)),
      count_(geometry.instanced_triangles()) {
  if (!settings || !settings->animated()) return;
  motion_.assign(geometry.instances.size(), kNoHit);
  for (const auto& [instance, motion] : settings->moving) motion_[instance] = motion;
}

FlatTriangles::Place FlatTriangles::locate(uint64_t tri) const {
  if (flat_) return {0, uint32_t(tri)};
  auto at = std::upper_bound(offsets_.begin(), offsets_.end(), tri) - 1;
  return {uint32_t(at - offsets_.begin()), uint32_t(tri - *at)};
}

const TriangleAlpha* FlatTriangles::alpha(uint64_t tri, uint32_t& prim) const {
  Place at = locate(tri);
  prim = at.prim;
  if (flat_) return flat_->alpha.get();
  return instances_->meshes[instances_->instances[at.instance].mesh].alpha.get();
}

std::array<glm::vec3, 3> FlatTriangles::corners(uint64_t tri, uint32_t frame) const {
  if (flat_) return flat_->corners(tri);
  Place at = locate(tri);
  const Instance& inst = instances_->instances[at.instance];
  const TriangleMesh& mesh = instances_->meshes[inst.mesh];
  const Transform* to_world = &inst.to_world;
  Transform posed;
  if (!motion_.empty() && motion_[at.instance] != kNoHit) {
    posed = pose_at(inst.to_world, settings_->motions[motion_[at.instance]],
                    settings_->pose_frame(frame), settings_->frames);
    to_world = &posed;
  }
  return {to_world->point(mesh.vertex(at.prim, 0)), to_world->point(mesh.vertex(at.prim, 1)),
          to_world->point(mesh.vertex(at.prim, 2))};
}

Bounds FlatTriangles::bounds() const {
  if (flat_) return mesh_bounds(*flat_);
  // Bounds::grow is out of line: a 100M-triangle forest transforms ~10^8 vertices here.
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const Instance& inst : instances_->instances)
    for (const glm::vec3& object : instances_->meshes[inst.mesh].positions) {
      glm::vec3 p = inst.to_world.point(object);
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  Bounds b;
  b.lo = lo;
  b.hi = hi;
  return b;
}

uint32_t FlatTriangles::flat_id(uint32_t instance, uint32_t prim) const {
  if (!instances_ || instance == kNoHit || prim == kNoHit || prim == kAnyPrim) return prim;
  return uint32_t(offsets_[instance] + prim);
}

}  // namespace rtsim
