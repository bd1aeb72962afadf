// rtsim trace WORKLOAD -o OUT.rays: run the hybrid pipeline of a workload spec (or a built-in
// scene with the default spec) and write its rays; --preview writes pictures of what it shot.
#include <fmt/core.h>
#include <unistd.h>

#include <cstdio>
#include <memory>
#include <optional>

#include "app/commands.h"
#include "reports/phase_progress.h"
#include "reports/cli_options.h"
#include "traces/error.h"
#include "workloads/pipeline/summary.h"
#include "workloads/pipeline/trace.h"

namespace rtsim::app {
namespace {

struct TraceArgs {
  std::string workload, output, preview, resolution, scene, camera, look_at, up;
  uint32_t frames = 0;
  uint64_t seed = 0;
  std::optional<uint32_t> camera_index;
  std::optional<double> fov;
  bool seed_set = false, quiet = false, list_keys = false;
};

void print_keys() {
  for (const auto& k : pipeline::spec_key_docs())
    fmt::print("{:<34} {:<22} default {}{}\n    {}\n", k.key, k.type,
               k.default_value.empty() ? "-" : k.default_value,
               k.unit.empty() ? "" : " (" + k.unit + ")", k.description);
}

}  // namespace

void add_trace_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "trace", "Generate the ray stream of a workload (spec file or built-in scene)");
  auto a = std::make_shared<TraceArgs>();
  cmd->add_option("workload", a->workload,
                  "Workload spec (.toml), or a scene (built-in or file) with the default spec");
  cmd->add_option("-o,--output", a->output, "Ray stream to write (.rays)");
  cmd->add_option("--frames", a->frames, "Frames to trace (overrides the spec)")
      ->check(reports::frame_range());
  cmd->add_option("--resolution", a->resolution, "Image size WxH (overrides the spec)");
  cmd->add_option("--seed", a->seed, "Random seed (overrides the spec)")
      ->check(reports::non_negative())
      ->each([a](const std::string&) { a->seed_set = true; });
  cmd->add_option("--scene", a->scene, "Scene file or built-in (replaces the spec's scene)");
  reports::add_camera_options(*cmd, a->camera, a->look_at, a->up, a->camera_index, a->fov);
  cmd->add_option("--preview", a->preview,
                  "Write a shaded PNG of the last frame, and PATH.density-PASS.png per pass");
  cmd->add_flag("-q,--quiet", a->quiet, "No progress and no summary");
  cmd->add_flag("--list-keys", a->list_keys, "List every workload spec key and exit");
  cmd->callback([a, &exit_code] {
    if (a->list_keys) {
      print_keys();
      exit_code = 0;
      return;
    }
    if (a->workload.empty()) throw InputError("trace: a workload (spec file or scene) is needed");
    if (a->output.empty() && a->preview.empty())
      throw InputError("trace: nothing to write: give -o OUT.rays and/or --preview OUT.png");
    pipeline::WorkloadSpec spec = pipeline::load_workload(a->workload);
    pipeline::apply_overrides(
        spec, pipeline::make_overrides(
                  {a->resolution, a->frames,
                   a->seed_set ? std::optional<uint64_t>(a->seed) : std::nullopt, a->scene,
                   a->camera, a->look_at, a->up, a->camera_index, a->fov}));
    pipeline::TraceOptions options;
    options.output = a->output;
    options.preview = a->preview;
    options.generator = "rtsim " RTSIM_VERSION;
    if (!a->quiet) options.progress = reports::trace_progress();
    pipeline::TraceResult result = pipeline::trace_workload(spec, options);
    if (!a->quiet) {
      for (const std::string& note : result.notes) fmt::print(stderr, "trace: {}\n", note);
      fmt::print("{}", pipeline::format_summary(result.summary));
      if (!a->output.empty()) fmt::print("wrote {}\n", a->output);
      for (const auto& image : result.images) fmt::print("wrote {}\n", image);
    }
    exit_code = 0;
  });
}

}  // namespace rtsim::app
