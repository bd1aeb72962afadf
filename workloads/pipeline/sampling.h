// Samplers and microfacet helpers used by the passes. Formulas follow PBRT (Pharr, Jakob,
// Humphreys, 3rd ed.): Halton radical inverse (7.4), Cranley-Patterson rotation (7.2.4),
// concentric-disk cosine hemisphere (13.6.3), uniform sphere and cone (13.6.1, 13.6.4), and
// GGX / Trowbridge-Reitz NDF sampling (Walter et al. 2007). Directions are unit vectors.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace rtsim::pipeline {

constexpr float kPi = 3.14159265358979323846f;

// Radical inverse of index in base 2 or 3 (the first two Halton dimensions).
float halton(uint32_t index, int base);

// Shifts a point of a low-discrepancy set by a per-pixel offset, modulo 1.
glm::vec2 cranley_patterson(glm::vec2 point, glm::vec2 rotation);

// Orthonormal basis around a unit normal (Duff et al. 2017, branchless).
struct Basis {
  glm::vec3 t, b, n;
  explicit Basis(const glm::vec3& normal);
  glm::vec3 to_world(const glm::vec3& local) const {
    return local.x * t + local.y * b + local.z * n;
  }
  glm::vec3 to_local(const glm::vec3& w) const;
};

glm::vec3 sample_cosine_hemisphere(glm::vec2 u);  // local, z up; pdf = cos / pi
glm::vec3 sample_uniform_sphere(glm::vec2 u);     // pdf = 1 / (4 pi)
glm::vec3 sample_uniform_cone(glm::vec2 u,
                              float cos_max);  // local, z axis; pdf = 1/(2pi(1-cos_max))

// GGX normal distribution D(h) for cos_theta_h = n.h, alpha = roughness^2.
float ggx_d(float cos_theta_h, float alpha);
// A microfacet normal (local, z up) sampled with density D(h) cos_theta_h; exactly the normal
// for alpha <= 1e-4 (roughness 0 is a perfect mirror).
glm::vec3 sample_ggx_half_vector(glm::vec2 u, float alpha);
// Density of the reflected direction l = reflect(-v, h) in solid angle, all local, z up.
float ggx_reflection_pdf(const glm::vec3& v, const glm::vec3& l, float alpha);

// Schlick's Fresnel approximation.
float schlick(float f0, float cos_theta);
// Reflectance at normal incidence of a dielectric with index ior in air.
float dielectric_f0(float ior);

glm::vec3 reflect_dir(const glm::vec3& incident, const glm::vec3& normal);
// Refracts incident (pointing toward the surface) through normal (facing incident's origin)
// with eta = n_incident / n_transmitted; false on total internal reflection.
bool refract_dir(const glm::vec3& incident, const glm::vec3& normal, float eta, glm::vec3& out);

}  // namespace rtsim::pipeline
