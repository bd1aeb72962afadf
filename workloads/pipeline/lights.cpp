#include "workloads/pipeline/lights.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <unordered_set>

#include "workloads/pipeline/offset.h"
#include "workloads/pipeline/sampling.h"

namespace rtsim::pipeline {
namespace {

struct EmissiveTriangle {
  std::array<glm::vec3, 3> corners;
  uint32_t object = 0;
  glm::vec3 emission{0.0f};
};

// The scene's emissive triangles in world space. An unflattened scene's are looked for only in
// the instances whose object makes some material of their mesh emissive.
std::vector<EmissiveTriangle> emissive_triangles(const Scene& scene,
                                                 const MaterialTable& materials) {
  std::vector<EmissiveTriangle> out;
  const FlatTriangles& triangles = materials.triangles;
  auto add = [&](uint64_t tri) {
    const ShadingMaterial& m = materials.of(uint32_t(tri));
    if (m.emissive())
      out.push_back({triangles.corners(tri), scene.attributes(triangles, tri).object, m.emission});
  };
  if (scene.flattened()) {
    for (uint64_t tri = 0; tri < triangles.count(); ++tri) add(tri);
    return out;
  }
  std::unordered_set<uint32_t> emitting;  // objects with an emissive material
  for (const auto& [key, index] : materials.of_pair)
    if (materials.materials[index].emissive()) emitting.insert(uint32_t(key >> 32));
  std::vector<uint64_t> offsets = flat_offsets(scene.instanced);
  for (size_t i = 0; i < scene.instanced.instances.size(); ++i) {
    uint32_t mesh = scene.instanced.instances[i].mesh;
    if (!emitting.count(scene.instance_object_ids[i])) continue;
    for (uint64_t prim = 0; prim < scene.instanced.meshes[mesh].triangle_count(); ++prim)
      add(offsets[i] + prim);
  }
  return out;
}

// One spherical light per emissive object, placed so that shadow rays end before they reach
// the emitter's own triangles (which stay in the scene).
void add_emissive_lights(const Scene& scene, const MaterialTable& materials, float diagonal,
                         std::vector<Light>& out) {
  struct Acc {
    double area = 0.0;
    glm::dvec3 centroid{0.0}, normal{0.0}, power{0.0};
  };
  std::vector<Acc> acc(std::max<size_t>(scene.object_names.size(), 1));
  std::vector<EmissiveTriangle> emissive = emissive_triangles(scene, materials);
  for (const EmissiveTriangle& e : emissive) {
    glm::dvec3 v0 = e.corners[0], v1 = e.corners[1], v2 = e.corners[2];
    glm::dvec3 cross = glm::cross(v1 - v0, v2 - v0);
    double area = 0.5 * glm::length(cross);
    if (!(area > 0.0)) continue;
    Acc& a = acc[std::min<size_t>(e.object, acc.size() - 1)];
    glm::dvec3 centre = (v0 + v1 + v2) / 3.0;
    glm::dvec3 n = cross / (2.0 * area);
    if (glm::dot(n, glm::dvec3(scene.bounds.center()) - centre) < 0.0) n = -n;
    a.area += area;
    a.centroid += centre * area;
    a.normal += n * area;
    a.power += glm::dvec3(e.emission) * area;
  }
  for (size_t obj = 0; obj < acc.size(); ++obj) {
    const Acc& a = acc[obj];
    if (a.area <= 0.0) continue;
    Light l;
    l.type = LightType::Sphere;
    glm::dvec3 centroid = a.centroid / a.area;
    double gap = 1e-3 * diagonal;
    if (glm::length(a.normal) > 0.5 * a.area) {
      // Flat (a panel): a sphere of the panel's equal-area disk radius, just in front of it.
      // A Lambertian emitter of radiance L and area A has intensity L A along its normal.
      glm::dvec3 n = glm::normalize(a.normal);
      l.radius = float(std::sqrt(a.area / 3.14159265358979));
      l.position = glm::vec3(centroid + n * (l.radius + gap));
      l.intensity = glm::vec3(a.power);
    } else {
      // Closed (a bulb): a sphere around it; a convex emitter shows a quarter of its area.
      double reach = 0.0;
      for (const EmissiveTriangle& e : emissive) {
        if (std::min<size_t>(e.object, acc.size() - 1) != obj) continue;
        for (const glm::vec3& corner : e.corners)
          reach = std::max(reach, glm::length(glm::dvec3(corner) - centroid));
      }
      l.radius = float(reach + gap);
      l.position = glm::vec3(centroid);
      l.intensity = glm::vec3(0.25 * a.power);
    }
    out.push_back(l);
  }
}

}  // namespace

std::vector<Light> resolve_lights(const WorkloadSpec& spec, const Scene& scene,
                                  const MaterialTable& materials) {
  std::vector<Light> lights;
  float diagonal = glm::length(scene.bounds.extent());
  glm::vec3 auto_position = scene.bounds.center();
  auto_position.y = scene.bounds.lo.y + 0.9f * scene.bounds.extent().y;
  for (const LightSpec& s : spec.lights) {
    Light l;
    l.type = s.type;
    l.position = s.position.value_or(auto_position);
    l.direction = glm::normalize(s.direction);
    l.intensity = s.color * s.intensity;
    l.radius = s.type == LightType::Sphere ? s.radius.value_or(0.005f * diagonal) : 0.0f;
    l.cos_cone = std::cos(s.cone_angle * kPi / 180.0f);
    l.cos_sun = std::cos(0.5f * s.angular_diameter * kPi / 180.0f);
    lights.push_back(l);
  }
  if (spec.lights_from_emission) add_emissive_lights(scene, materials, diagonal, lights);
  return lights;
}

bool make_shadow_ray(const Light& light, const glm::vec3& p, const glm::vec3& n, glm::vec2 u,
                     Ray& ray) {
  if (light.intensity == glm::vec3(0.0f)) return false;
  glm::vec3 dir;
  float tmax = std::numeric_limits<float>::infinity();
  if (light.type == LightType::Directional) {
    dir = -light.direction;
    if (light.cos_sun < 1.0f) dir = Basis(dir).to_world(sample_uniform_cone(u, light.cos_sun));
  } else {
    glm::vec3 to_light = light.position - p;
    float dist = glm::length(to_light);
    if (!(dist > 0.0f)) return false;
    glm::vec3 axis = to_light / dist;
    if (light.type == LightType::Spot && glm::dot(-axis, light.direction) < light.cos_cone)
      return false;
    if (light.type != LightType::Sphere || light.radius <= 0.0f) {
      dir = axis;
      tmax = dist;
    } else {
      if (dist <= light.radius) return false;
      float sin2 = (light.radius * light.radius) / (dist * dist);
      float cos_max = std::sqrt(std::max(0.0f, 1.0f - sin2));
      dir = Basis(axis).to_world(sample_uniform_cone(u, cos_max));
      // The shadow ray ends where dir first meets the sphere.
      float b = glm::dot(dir, to_light);
      float disc = b * b - (dist * dist - light.radius * light.radius);
      tmax = b - std::sqrt(std::max(0.0f, disc));
    }
  }
  if (glm::dot(dir, n) <= 0.0f) return false;
  ray.org = offset_ray_origin(p, n);
  ray.dir = dir;
  ray.tmin = 0.0f;
  ray.tmax = tmax;
  ray.query = Query::AnyHit;
  return true;
}

glm::vec3 light_irradiance(const Light& light, const glm::vec3& p, const glm::vec3& n) {
  if (light.type == LightType::Directional)
    return light.intensity * std::max(0.0f, glm::dot(n, -light.direction));
  glm::vec3 to_light = light.position - p;
  float d2 = std::max(glm::dot(to_light, to_light), 1e-8f);
  glm::vec3 l = to_light / std::sqrt(d2);
  if (light.type == LightType::Spot && glm::dot(-l, light.direction) < light.cos_cone)
    return glm::vec3(0.0f);
  return light.intensity * (std::max(0.0f, glm::dot(n, l)) / d2);
}

}  // namespace rtsim::pipeline
