// A pinhole camera, its automatic placement and its path over frames.
#pragma once

#include <cstdint>
#include <string>
#include <glm/vec3.hpp>

#include "traces/embree_scene.h"
#include "traces/ray.h"
#include "workloads/pipeline/spec.h"

namespace rtsim::pipeline {

struct Camera {
  glm::vec3 position{0.0f}, forward{0.0f, 0.0f, -1.0f}, right{1.0f, 0.0f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float tan_half_fov = 0.57735f;  // vertical
  uint32_t width = 1, height = 1;

  static Camera look_at(const glm::vec3& position, const glm::vec3& target, const glm::vec3& up,
                        float fov_degrees, uint32_t width, uint32_t height);
  // Unit direction through screen point (sx, sy) in pixels, (0, 0) the top-left corner.
  glm::vec3 direction(float sx, float sy) const;
  // Angle one pixel subtends at the image centre, radians.
  float pixel_angle() const { return 2.0f * tan_half_fov / float(height); }
};

struct View {
  glm::vec3 position{0.0f}, look_at{0.0f};
  std::string why;  // auto_view: what the probes found and where that put the camera
};

// A view that shows the scene: an outside three-quarter view that fits the bounding sphere,
// or, for an enclosed scene (an interior such as Sponza), a view from inside along its longest
// horizontal axis, or, for a level whose centre sees only back faces (rooms in a void), a view
// from inside its roomiest room. Probe rays decide which (see workloads/README.md).
View auto_view(const FlatTriangles& triangles, const Bounds& bounds, const EmbreeScene& embree,
               const glm::vec3& up, float fov, float aspect);

// Why rays cannot start at p: beyond Embree's range (traces/ray.h); empty if fine. A camera
// fitted to the scene is held to this, not to the scene's range: it may stand outside a scene
// that fills that range.
std::string camera_origin_problem(const glm::vec3& p);

// The camera of frame `frame` of `frames`: auto parts filled by auto_view, then the keys or the
// orbit applied.
Camera camera_for_frame(const CameraSpec& spec, const View& auto_fit, uint32_t frame,
                        uint32_t frames, uint32_t width, uint32_t height);

}  // namespace rtsim::pipeline
