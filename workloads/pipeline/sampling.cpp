#include "workloads/pipeline/sampling.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace rtsim::pipeline {

float halton(uint32_t index, int base) {
  if (base == 2) {
    // Bit reversal is the base-2 radical inverse.
    uint32_t bits = index;
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x00ff00ffu) << 8u) | ((bits & 0xff00ff00u) >> 8u);
    bits = ((bits & 0x0f0f0f0fu) << 4u) | ((bits & 0xf0f0f0f0u) >> 4u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xccccccccu) >> 2u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xaaaaaaaau) >> 1u);
    return std::min(static_cast<float>(bits >> 8) * 0x1p-24f, 0x1.fffffep-1f);
  }
  double inv_base = 1.0 / base, f = inv_base, result = 0.0;
  for (uint32_t i = index; i > 0; i /= static_cast<uint32_t>(base)) {
    result += f * (i % static_cast<uint32_t>(base));
    f *= inv_base;
  }
  return std::min(static_cast<float>(result), 0x1.fffffep-1f);
}

glm::vec2 cranley_patterson(glm::vec2 point, glm::vec2 rotation) {
  glm::vec2 r = point + rotation;
  if (r.x >= 1.0f) r.x -= 1.0f;
  if (r.y >= 1.0f) r.y -= 1.0f;
  return glm::min(r, glm::vec2(0x1.fffffep-1f));
}

Basis::Basis(const glm::vec3& normal) : n(normal) {
  float sign = std::copysign(1.0f, n.z);
  float a = -1.0f / (sign + n.z);
  float b_ = n.x * n.y * a;
  t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * b_, -sign * n.x);
  b = glm::vec3(b_, sign + n.y * n.y * a, -n.y);
}

glm::vec3 Basis::to_local(const glm::vec3& w) const {
  return glm::vec3(glm::dot(w, t), glm::dot(w, b), glm::dot(w, n));
}

glm::vec3 sample_cosine_hemisphere(glm::vec2 u) {
  // Concentric map of the square to the disk, then project up to the hemisphere (Malley).
  glm::vec2 o = 2.0f * u - glm::vec2(1.0f);
  glm::vec2 d(0.0f);
  if (o.x != 0.0f || o.y != 0.0f) {
    float r, theta;
    if (std::abs(o.x) > std::abs(o.y)) {
      r = o.x;
      theta = (kPi / 4.0f) * (o.y / o.x);
    } else {
      r = o.y;
      theta = kPi / 2.0f - (kPi / 4.0f) * (o.x / o.y);
    }
    d = r * glm::vec2(std::cos(theta), std::sin(theta));
  }
  float z = std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
  return glm::vec3(d.x, d.y, z);
}

glm::vec3 sample_uniform_sphere(glm::vec2 u) {
  float z = 1.0f - 2.0f * u.x;
  float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  float phi = 2.0f * kPi * u.y;
  return glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
}

glm::vec3 sample_uniform_cone(glm::vec2 u, float cos_max) {
  float cos_theta = (1.0f - u.x) + u.x * cos_max;
  float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
  float phi = 2.0f * kPi * u.y;
  return glm::vec3(std::cos(phi) * sin_theta, std::sin(phi) * sin_theta, cos_theta);
}

float ggx_d(float cos_theta_h, float alpha) {
  if (cos_theta_h <= 0.0f) return 0.0f;
  float a2 = alpha * alpha;
  float c2 = cos_theta_h * cos_theta_h;
  float denom = c2 * (a2 - 1.0f) + 1.0f;
  return a2 / (kPi * denom * denom);
}

glm::vec3 sample_ggx_half_vector(glm::vec2 u, float alpha) {
  if (alpha <= 1e-4f) return glm::vec3(0.0f, 0.0f, 1.0f);  // a perfect mirror
  // tan^2(theta) = alpha^2 u / (1 - u) inverts the GGX marginal CDF of theta.
  float tan2 = alpha * alpha * u.x / std::max(1.0f - u.x, 1e-7f);
  float cos_theta = 1.0f / std::sqrt(1.0f + tan2);
  float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
  float phi = 2.0f * kPi * u.y;
  return glm::vec3(std::cos(phi) * sin_theta, std::sin(phi) * sin_theta, cos_theta);
}

float ggx_reflection_pdf(const glm::vec3& v, const glm::vec3& l, float alpha) {
  glm::vec3 h = v + l;
  float len = glm::length(h);
  if (len == 0.0f) return 0.0f;
  h /= len;
  float v_dot_h = glm::dot(v, h);
  if (v_dot_h <= 0.0f) return 0.0f;
  return ggx_d(h.z, alpha) * h.z / (4.0f * v_dot_h);
}

float schlick(float f0, float cos_theta) {
  float m = std::clamp(1.0f - cos_theta, 0.0f, 1.0f);
  float m2 = m * m;
  return f0 + (1.0f - f0) * m2 * m2 * m;
}

float dielectric_f0(float ior) {
  float r = (ior - 1.0f) / (ior + 1.0f);
  return r * r;
}

glm::vec3 reflect_dir(const glm::vec3& incident, const glm::vec3& normal) {
  return incident - 2.0f * glm::dot(incident, normal) * normal;
}

bool refract_dir(const glm::vec3& incident, const glm::vec3& normal, float eta, glm::vec3& out) {
  float cos_i = -glm::dot(incident, normal);
  float k = 1.0f - eta * eta * (1.0f - cos_i * cos_i);
  if (k < 0.0f) return false;
  out = glm::normalize(eta * incident + (eta * cos_i - std::sqrt(k)) * normal);
  return true;
}

}  // namespace rtsim::pipeline
