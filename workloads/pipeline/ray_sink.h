// Where passes put their rays: each ray is checked, written to the stream (if any), counted
// under its pass (and apart if tracing it met an alpha-tested candidate), and added to per-pass
// ray-density counts. Passes emit rays in the order the stream keeps them. Rays of the first
// warmup_frames frames only feed the frame's cost map; later frames are written renumbered
// from 0.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "traces/ray.h"
#include "traces/stream.h"

namespace rtsim::pipeline {

// Passes in the order they run in a frame. GiLight rays are shadow rays (RayType::Shadow) from
// GI hits; they are counted apart so each pass can be checked against its budget.
enum class PassId : uint8_t {
  Camera,
  Shadow,
  Reflection,
  ReflectedShadow,
  DiffuseGI,
  GiLight,
  AO,
  Refraction,
  Translucency,
};
constexpr int kPassCount = 9;

const char* pass_name(PassId pass);
RayType pass_ray_type(PassId pass);

class RaySink {
 public:
  // origin_prim: the triangle a secondary ray leaves from (kNoHit for camera rays).
  using Observer = std::function<void(const Ray&, PassId, uint32_t origin_prim)>;

  // writer may be null (count only). Density counts are kept when keep_density is set.
  RaySink(RayStreamWriter* writer, uint32_t width, uint32_t height, bool keep_density);
  // Frames before this one are the warm-up (the Pipeline sets it from its spec).
  void set_warmup_frames(uint32_t frames) { warmup_frames_ = frames; }

  void set_pass(PassId pass) { pass_ = pass; }
  PassId pass() const { return pass_; }
  // met_alpha: tracing the ray met an alpha-tested candidate (EmbreeScene::intersect, occluded).
  void emit(const Ray& ray, uint32_t origin_prim = kNoHit, bool met_alpha = false);

  uint64_t count(PassId pass) const { return counts_[size_t(pass)]; }
  // Of a pass's rays, those that met an alpha-tested candidate.
  uint64_t alpha_count(PassId pass) const { return alpha_counts_[size_t(pass)]; }
  uint64_t total() const;
  // Rays per pixel of one pass over the whole run (empty unless keep_density).
  const std::vector<uint32_t>& density(PassId pass) const { return density_[size_t(pass)]; }
  // Rays per pixel in the current frame, all passes: the cost map for importance sampling.
  std::vector<uint32_t>& frame_cost() { return frame_cost_; }

  Observer observer;

 private:
  RayStreamWriter* writer_;
  uint32_t warmup_frames_ = 0;
  PassId pass_ = PassId::Camera;
  std::array<uint64_t, kPassCount> counts_{};
  std::array<uint64_t, kPassCount> alpha_counts_{};
  std::array<std::vector<uint32_t>, kPassCount> density_;
  std::vector<uint32_t> frame_cost_;
};

}  // namespace rtsim::pipeline
