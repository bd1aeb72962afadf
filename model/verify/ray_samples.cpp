#include "model/verify/ray_samples.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace rtsim {

uint64_t SeededRandom::next() {
  uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

float SeededRandom::uniform() {
  return static_cast<float>(next() >> 40) * 0x1p-24f;
}

glm::vec3 random_direction(SeededRandom& random) {
  float z = 1.0f - 2.0f * random.uniform();
  float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  float phi = 6.28318530718f * random.uniform();
  return {r * std::cos(phi), r * std::sin(phi), z};
}

std::vector<Ray> sample_diffuse_rays(const FlatTriangles& triangles, size_t count, uint64_t seed) {
  // Cumulative areas, to pick triangles in proportion to their area.
  std::vector<double> cumulative(triangles.count());
  double total = 0.0;
  for (uint64_t i = 0; i < triangles.count(); ++i) {
    auto [a, b, c] = triangles.corners(i);
    total += 0.5 * glm::length(glm::cross(b - a, c - a));
    cumulative[i] = total;
  }
  float nudge = 1e-4f * glm::length(triangles.bounds().extent());
  SeededRandom random(seed);
  std::vector<Ray> rays;
  rays.reserve(count);
  while (rays.size() < count && total > 0.0) {
    double pick = double(random.uniform()) * total;
    size_t tri = std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin();
    tri = std::min<uint64_t>(tri, triangles.count() - 1);
    auto [a, b, c] = triangles.corners(tri);
    glm::vec3 n = glm::cross(b - a, c - a);
    if (!(glm::length(n) > 0.0f)) continue;
    n = glm::normalize(n);
    if (random.uniform() < 0.5f) n = -n;
    // Uniform point on the triangle.
    float s = std::sqrt(random.uniform()), t = random.uniform();
    glm::vec3 p = (1.0f - s) * a + s * (1.0f - t) * b + s * t * c;
    // Cosine-distributed direction about n.
    glm::vec3 dir = glm::normalize(n + random_direction(random));
    if (!(glm::dot(dir, n) > 1e-3f)) continue;
    Ray ray;
    ray.org = p + nudge * n;
    ray.dir = dir;
    ray.type = RayType::DiffuseGI;
    ray.pixel = static_cast<uint32_t>(rays.size());
    rays.push_back(ray);
  }
  return rays;
}

std::vector<Ray> sample_camera_rays(const FlatTriangles& triangles, uint32_t width, uint32_t height,
                                    float distance) {
  Bounds bounds = triangles.bounds();
  glm::vec3 center = bounds.center();
  float radius = 0.5f * glm::length(bounds.extent());
  glm::vec3 eye = center + glm::vec3(0.3f, 0.4f, 1.0f) * (distance * radius);
  glm::vec3 forward = glm::normalize(center - eye);
  glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
  glm::vec3 up = glm::cross(right, forward);
  std::vector<Ray> rays;
  rays.reserve(size_t(width) * height);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      float px = (2.0f * (x + 0.5f) / width - 1.0f) * 0.6f;
      float py = (1.0f - 2.0f * (y + 0.5f) / height) * 0.6f * height / width;
      Ray ray;
      ray.org = eye;
      ray.dir = glm::normalize(forward + px * right + py * up);
      ray.pixel = y * width + x;
      rays.push_back(ray);
    }
  return rays;
}

std::vector<Ray> sample_random_rays(const FlatTriangles& triangles, size_t count, uint64_t seed,
                                    float margin) {
  Bounds bounds = triangles.bounds();
  glm::vec3 grow(margin * glm::length(bounds.extent()));
  glm::vec3 lo = bounds.lo - grow, size = bounds.extent() + 2.0f * grow;
  SeededRandom random(seed);
  std::vector<Ray> rays(count);
  for (size_t i = 0; i < count; ++i) {
    rays[i].org = lo + size * glm::vec3(random.uniform(), random.uniform(), random.uniform());
    rays[i].dir = random_direction(random);
    rays[i].pixel = static_cast<uint32_t>(i);
  }
  return rays;
}

}  // namespace rtsim
