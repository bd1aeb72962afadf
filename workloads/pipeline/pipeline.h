// The hybrid pipeline of one workload: per frame, the camera pass fills the G-buffer, then
// shadow, reflection, reflected-shadow, diffuse GI (+ light connections), AO, refraction and
// translucency passes shoot their rays, in that order, into a RaySink. A pass with nothing to
// do shoots nothing and says why; the summary collects it.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "workloads/pipeline/context.h"
#include "workloads/pipeline/gbuffer.h"
#include "workloads/pipeline/pass_ao.h"
#include "workloads/pipeline/pass_reflected_shadow.h"
#include "workloads/pipeline/pass_reflection.h"
#include "workloads/pipeline/pass_refraction.h"
#include "workloads/pipeline/pass_shadow.h"
#include "workloads/pipeline/pass_translucency.h"
#include "workloads/pipeline/ray_sink.h"
#include "workloads/pipeline/samples.h"
#include "workloads/pipeline/surfels.h"

namespace rtsim::pipeline {

struct FrameResults {
  Camera camera;
  GBuffer gbuffer;
  ShadowResult shadow;
  ReflectionResult reflection;
  ReflectedShadowResult reflected_shadow;
  AoResult ao;
  RefractionResult refraction;
  TranslucencyResult translucency;
};

struct PassSummary {
  uint64_t rays = 0;
  uint64_t alpha_rays = 0;            // of them, those that met an alpha-tested candidate
  uint64_t budget = 0;                // most rays the settings allow per frame
  double budget_per_pixel_1080p = 0;  // the same settings' budget a pixel at 1920x1080
  uint32_t frames_skipped = 0;        // frames in which it shot nothing
  std::string reason;                 // why (from the first such frame)
};

struct RunSummary {
  std::string workload, scene_source;
  uint64_t triangles = 0;
  uint32_t width = 0, height = 0, frames = 0;
  size_t lights = 0, surfels = 0;
  glm::vec3 camera_position{0.0f}, camera_look_at{0.0f};  // of frame 0
  std::array<PassSummary, kPassCount> passes;
  double load_seconds = 0.0, build_seconds = 0.0, trace_seconds = 0.0;

  uint64_t total_rays() const;
  uint64_t total_alpha_rays() const;
};

// The resolution the presets' budgets are set for (SEED's 1080p frame): the ray mix a pass's
// budget per pixel is compared with (summary.h, ray_mix_note).
constexpr uint32_t kMixWidth = 1920, kMixHeight = 1080;

// The most rays a pass may shoot in one frame under these settings.
uint64_t pass_budget(const WorkloadSpec& spec, PassId pass, size_t lights);

class Pipeline {
 public:
  Pipeline(const WorkloadSpec& spec, const Scene& scene, const EmbreeScene& embree);

  // Runs every pass of one frame; frames must be run in order from 0. The first
  // spec.warmup_frames of them are the warm-up: at frame 0's camera, not in the summary, and
  // the sink drops their rays (it writes the others numbered from 0).
  void run_frame(uint32_t frame, RaySink& sink, FrameResults& results);
  // How many frames to run: the warm-up and the recorded ones.
  uint32_t frames_to_run() const { return spec_.warmup_frames + spec_.frames; }

  const SceneContext& scene() const { return scene_; }
  const SurfelCache& surfels() const { return surfels_; }
  const WorkloadSpec& spec() const { return spec_; }
  const View& auto_fit() const { return auto_fit_; }
  RunSummary& summary() { return summary_; }

  // Called before each pass runs (progress reporting).
  std::function<void(uint32_t frame, PassId pass)> on_pass;

 private:
  std::vector<SamplePosition> place_samples(const FrameContext& ctx, RaySink& sink);
  void record(PassId pass, const PassOutcome& outcome);
  void enter(uint32_t frame, PassId pass);

  WorkloadSpec spec_;
  MaterialTable materials_;
  SceneContext scene_;
  View auto_fit_;
  SurfelCache surfels_;
  RunSummary summary_;
  GBuffer previous_;  // last frame's G-buffer (importance placement)
  bool warming_up_ = false;
  std::vector<uint32_t> previous_cost_;
};

}  // namespace rtsim::pipeline
