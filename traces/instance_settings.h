// What a workload sets on the instances of a scene kept as instances: visibility masks (DXR's
// InstanceMask against the InstanceInclusionMask of each ray type) and motion along keys over
// the frames. The stream header records it (traces/FORMAT.md), so every later command sees the
// scene as it was traced; the pipeline, the Embree reference and the model all apply it.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "traces/instances.h"

namespace rtsim {

// Where an instance stands at one key, relative to where the scene places it: scaled and turned
// about its own origin, then moved.
struct MotionKey {
  glm::vec3 translate{0.0f};  // world units
  float rotate = 0.0f;        // degrees about the motion's axis
  float scale = 1.0f;         // uniform
};

// Keys spread evenly over the frames (the first at frame 0, the last at the last frame), linear
// in between, as camera keys are.
struct Motion {
  glm::vec3 axis{0.0f, 1.0f, 0.0f};  // unit length, in world space
  std::vector<MotionKey> keys;
};

// Every ray type sees every instance.
inline std::array<uint8_t, kRayTypeCount> all_ray_masks() {
  std::array<uint8_t, kRayTypeCount> masks;
  masks.fill(kAllInstances);
  return masks;
}

struct InstanceSettings {
  std::array<uint8_t, kRayTypeCount> ray_masks = all_ray_masks();  // per RayType: masks it sees
  std::vector<std::pair<uint32_t, uint8_t>> masks;  // (instance, mask), ascending; others 0xFF
  std::vector<Motion> motions;
  std::vector<std::pair<uint32_t, uint32_t>> moving;  // (instance, motion), ascending
  uint32_t frames = 1;                                // what the keys spread over
  // Frames before frame 0 that stand at frame 0's pose: a pipeline's warm-up frames, whose rays
  // carry frame numbers counted from the first of them (0 in a stream, not recorded).
  uint32_t still_frames = 0;

  // Nothing set: every ray sees every instance, nothing moves.
  bool empty() const;
  bool animated() const { return !moving.empty(); }
  // The pose (0 .. frames - 1) a ray of `frame` sees.
  uint32_t pose_frame(uint32_t frame) const {
    return frame <= still_frames ? 0 : std::min(frame - still_frames, frames - 1);
  }
  bool operator==(const InstanceSettings& o) const;
};

// Why settings cannot apply to a scene of `instances` instances (an instance or motion index out
// of range or out of order, a ray mask of 0, a motion without keys, a value that is not finite,
// an axis that is not of unit length, a scale that is not positive); empty if fine.
std::string settings_problem(const InstanceSettings& settings, size_t instances);

// Where a point t in [0, 1] of a run (frame / (frames - 1)) falls among `keys` keys spread evenly
// over it: between keys i and j (i or i + 1) at fraction f. Camera keys and motion keys alike.
struct KeyBlend {
  size_t i = 0, j = 0;
  float f = 0.0f;
};
KeyBlend blend_keys(float t, size_t keys);

// The transform of an instance the scene places by `placed`, at `frame` under `motion`.
Transform pose_at(const Transform& placed, const Motion& motion, uint32_t frame, uint32_t frames);

// Sets the settings' masks on the instances (the others to 0xFF).
void apply_masks(InstancedMesh& geometry, const InstanceSettings& settings);

// The instances as they stand in pose `frame` (0 .. frames - 1): the moving ones posed, the
// others as placed.
std::vector<Instance> instances_at(const std::vector<Instance>& placed,
                                   const InstanceSettings& settings, uint32_t frame);

}  // namespace rtsim
