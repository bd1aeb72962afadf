#include "workloads/pipeline/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>

#include <fmt/format.h>

#include "traces/instance_settings.h"
#include "workloads/pipeline/offset.h"
#include "workloads/pipeline/sampling.h"

namespace rtsim::pipeline {
namespace {

glm::vec3 rotate_about(const glm::vec3& v, const glm::vec3& axis, float radians) {
  float c = std::cos(radians), s = std::sin(radians);
  return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0f - c);
}

struct Probe {
  float hit_fraction = 0.0f, front_fraction = 0.0f, median_t = 0.0f;
};

// Shoots rays in `count` directions spread over the sphere (a Fibonacci lattice).
Probe probe_from(const FlatTriangles& triangles, const EmbreeScene& embree, const glm::vec3& origin,
                 int count) {
  std::vector<float> ts;
  int front = 0;
  for (int i = 0; i < count; ++i) {
    float z = 1.0f - (2.0f * float(i) + 1.0f) / float(count);
    float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    float phi = float(i) * 2.39996323f;
    Ray ray;
    ray.org = origin;
    ray.dir = glm::vec3(r * std::cos(phi), z, r * std::sin(phi));
    Hit hit = triangles.flat(embree.intersect(ray));
    if (!hit.hit()) continue;
    ts.push_back(hit.t);
    if (glm::dot(face_normal(triangles.corners(hit.prim)), ray.dir) < 0.0f) ++front;
  }
  Probe p;
  if (ts.empty()) return p;
  std::nth_element(ts.begin(), ts.begin() + long(ts.size() / 2), ts.end());
  p.median_t = ts[ts.size() / 2];
  p.hit_fraction = float(ts.size()) / float(count);
  p.front_fraction = float(front) / float(ts.size());
  return p;
}

// Mean free distance (capped at cap) over a 5x5 fan of rays around dir, spread over +-0.5
// across and up: a whole side of the view, not one ray that may hit a small object.
float free_distance(const EmbreeScene& embree, const glm::vec3& origin, const glm::vec3& dir,
                    const glm::vec3& up, float cap) {
  glm::vec3 across = glm::cross(dir, up);
  float sum = 0.0f;
  for (int i = -2; i <= 2; ++i)
    for (int j = -2; j <= 2; ++j) {
      Ray ray;
      ray.org = origin;
      ray.dir = glm::normalize(dir + across * (0.25f * float(i)) + up * (0.25f * float(j)));
      Hit hit = embree.intersect(ray);
      sum += hit.hit() ? std::min(hit.t, cap) : cap;
    }
  return sum / 25.0f;
}

float coverage(const EmbreeScene& embree, const glm::vec3& position, const glm::vec3& target,
               const glm::vec3& up, float fov, float aspect) {
  constexpr uint32_t kH = 18;
  auto w = std::max<uint32_t>(1, uint32_t(std::lround(kH * aspect)));
  Camera cam = Camera::look_at(position, target, up, fov, w, kH);
  int hits = 0;
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      Ray ray;
      ray.org = cam.position;
      ray.dir = cam.direction(float(x) + 0.5f, float(y) + 0.5f);
      hits += embree.intersect(ray).hit() ? 1 : 0;
    }
  return float(hits) / float(w * kH);
}

// A room of a level whose centre lies outside every room (a game map: rooms in a void, their
// outer faces not modelled): the candidate eye point on a grid through the bounds from which
// nearly every direction meets a front face, with the most room around it. Looks along the
// longest free horizontal direction. False if no candidate is inside a room.
bool room_view(const FlatTriangles& triangles, const EmbreeScene& embree, const glm::vec3& c,
               const Basis& basis, const glm::vec3& half, View& view) {
  constexpr int kGrid = 6;
  float best = 0.0f;
  glm::vec3 eye(0.0f);
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j)
      for (float height : {-0.3f, 0.2f}) {
        glm::vec3 local((2.0f * float(i) + 1.0f) / kGrid - 1.0f,
                        (2.0f * float(j) + 1.0f) / kGrid - 1.0f, height);
        glm::vec3 p = c + basis.to_world(local * half);
        Probe probe = probe_from(triangles, embree, p, 64);
        if (probe.hit_fraction >= 0.95f && probe.front_fraction >= 0.9f && probe.median_t > best) {
          best = probe.median_t;
          eye = p;
        }
      }
  if (best <= 0.0f) return false;
  view.why = fmt::format(
      "probes from the centre met mostly back faces (rooms in a void): inside the roomiest room "
      "that probes from a {0} x {0} x 2 grid found, along its longest free horizontal direction",
      kGrid);
  float longest = -1.0f;
  for (int k = 0; k < 8; ++k) {
    float a = float(k) * kPi / 4.0f;
    glm::vec3 dir = std::cos(a) * basis.t + std::sin(a) * basis.b;
    float free = free_distance(embree, eye, dir, basis.n, 2.0f * glm::length(half));
    if (free > longest) {
      longest = free;
      view.position = eye;
      view.look_at = eye + dir * free;
    }
  }
  return true;
}

}  // namespace

std::string camera_origin_problem(const glm::vec3& p) {
  Ray ray;
  ray.org = p;
  ray.dir = glm::vec3(0.0f, 0.0f, -1.0f);
  return ray_problem(ray);
}

Camera Camera::look_at(const glm::vec3& position, const glm::vec3& target, const glm::vec3& up,
                       float fov_degrees, uint32_t width, uint32_t height) {
  Camera c;
  c.position = position;
  glm::vec3 forward = target - position;
  c.forward = glm::length(forward) > 0.0f ? glm::normalize(forward) : glm::vec3(0, 0, -1);
  glm::vec3 right = glm::cross(c.forward, up);
  if (glm::length(right) < 1e-6f) right = glm::cross(c.forward, glm::vec3(1, 0, 0));
  if (glm::length(right) < 1e-6f) right = glm::cross(c.forward, glm::vec3(0, 0, 1));
  c.right = glm::normalize(right);
  c.up = glm::cross(c.right, c.forward);
  c.tan_half_fov = std::tan(0.5f * fov_degrees * kPi / 180.0f);
  c.width = width;
  c.height = height;
  return c;
}

glm::vec3 Camera::direction(float sx, float sy) const {
  float aspect = float(width) / float(height);
  float px = (2.0f * sx / float(width) - 1.0f) * tan_half_fov * aspect;
  float py = (1.0f - 2.0f * sy / float(height)) * tan_half_fov;
  return glm::normalize(forward + px * right + py * up);
}

View auto_view(const FlatTriangles& triangles, const Bounds& bounds, const EmbreeScene& embree,
               const glm::vec3& up_in, float fov, float aspect) {
  glm::vec3 up = glm::normalize(up_in);
  glm::vec3 c = bounds.center();
  float radius = 0.5f * glm::length(bounds.extent());
  Basis basis(up);
  // Half extents along the two horizontal axes and up, from the 8 corners.
  glm::vec3 half(0.0f);
  for (int i = 0; i < 8; ++i) {
    glm::vec3 corner((i & 1) ? bounds.hi.x : bounds.lo.x, (i & 2) ? bounds.hi.y : bounds.lo.y,
                     (i & 4) ? bounds.hi.z : bounds.lo.z);
    half = glm::max(half, glm::abs(basis.to_local(corner - c)));
  }
  glm::vec3 eye_level = c - up * (0.15f * 2.0f * half.z);
  Probe probe = probe_from(triangles, embree, eye_level, 64);
  bool enclosed = probe.hit_fraction >= 0.7f && probe.front_fraction >= 0.5f &&
                  probe.median_t >= 0.15f * radius;
  std::string found = fmt::format(
      "{:.0f}% of 64 probes from the centre hit, {:.0f}% of those front faces, at a median {:.2g} "
      "of the bounding radius",
      100.0f * probe.hit_fraction, 100.0f * probe.front_fraction,
      radius > 0.0f ? probe.median_t / radius : 0.0f);
  View view;
  float half_fov = 0.5f * fov * kPi / 180.0f;
  float tan_v = std::tan(half_fov), tan_h = tan_v * aspect;
  if (enclosed) {
    // The most open horizontal side: stand there and look across to the opposite one.
    glm::vec3 best_dir = basis.t;
    float best_free = -1.0f, best_half = half.x, other_half = half.y;
    const glm::vec3 dirs[4] = {basis.t, basis.b, -basis.t, -basis.b};
    const float halves[4] = {half.x, half.y, half.x, half.y};
    for (int i = 0; i < 4; ++i) {
      float free = free_distance(embree, eye_level, dirs[i], up, 4.0f * halves[i]);
      if (free > best_free * 1.05f) {
        best_free = free;
        best_dir = dirs[i];
        best_half = halves[i];
        other_half = halves[(i + 1) % 4];
      }
    }
    if (best_free >= 3.0f * best_half) {
      // An open side (a Cornell box): look in through it, framing the opening.
      float fit = std::max(other_half / tan_h, half.z / tan_v);
      view.position = c + best_dir * (best_half + fit);
      view.look_at = c;
      view.why = "an enclosure open on one side (" + found + "): outside the opening, framing it";
      return view;
    }
    view.position = eye_level + best_dir * (0.8f * std::min(best_free, best_half));
    view.look_at = eye_level - best_dir * best_half + up * (0.1f * half.z);
    view.why = "an enclosure (" + found +
               "): inside, near its most open horizontal side, looking across to the other";
    return view;
  }
  if (probe.front_fraction < 0.5f && room_view(triangles, embree, c, basis, half, view))
    return view;
  float half_fov_min = std::min(half_fov, std::atan(tan_h));
  float distance = radius / std::sin(half_fov_min);
  float best = -1.0f;
  for (int i = 0; i < 4; ++i) {
    float azimuth = (45.0f + 90.0f * float(i)) * kPi / 180.0f;
    float elevation = 25.0f * kPi / 180.0f;
    glm::vec3 dir =
        std::cos(elevation) * (std::cos(azimuth) * basis.t + std::sin(azimuth) * basis.b) +
        std::sin(elevation) * up;
    glm::vec3 position = c + dir * distance;
    // Too far out to trace from (a narrow view of a huge scene): not probed; if none can be,
    // the first is returned for the pipeline to refuse.
    float cov = camera_origin_problem(position).empty()
                    ? coverage(embree, position, c, up, fov, aspect)
                    : -0.5f;
    if (cov > best + 1e-3f) {
      best = cov;
      view.position = position;
      view.look_at = c;
    }
  }
  view.why = fmt::format(
      "an object, not an enclosure ({}): outside, 25 degrees up, at the diagonal where the scene "
      "covers most of a probe image ({:.0f}%), far enough to fit its bounding sphere",
      found, 100.0f * std::max(best, 0.0f));
  return view;
}

Camera camera_for_frame(const CameraSpec& spec, const View& auto_fit, uint32_t frame,
                        uint32_t frames, uint32_t width, uint32_t height) {
  glm::vec3 position = spec.position.value_or(auto_fit.position);
  glm::vec3 target = spec.look_at.value_or(auto_fit.look_at);
  float t = frames > 1 ? float(frame) / float(frames - 1) : 0.0f;
  if (!spec.keys.empty()) {
    auto [i, j, f] = blend_keys(t, spec.keys.size());
    position = glm::mix(spec.keys[i].position, spec.keys[j].position, f);
    target = glm::mix(spec.keys[i].look_at, spec.keys[j].look_at, f);
  }
  if (spec.orbit != 0.0f) {
    float angle = t * spec.orbit * kPi / 180.0f;
    position = target + rotate_about(position - target, glm::normalize(spec.up), angle);
  }
  return Camera::look_at(position, target, spec.up, spec.fov, width, height);
}

}  // namespace rtsim::pipeline
