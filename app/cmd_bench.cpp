// rtsim bench: the functional model against Embree (both single-threaded, same process, same
// rays): diffuse-GI-like rays on a scene, default 1M rays on Conference. Each side runs
// --repeat times, alternating, and the fastest run of each counts, since the machines are
// noisy. Prints both times and their ratio (target: the model within 3x of Embree).
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>

#include "app/commands.h"
#include "reports/cli_options.h"
#include "model/bvh/bvh_image.h"
#include "model/units/traversal.h"
#include "model/verify/ray_samples.h"
#include "traces/embree_scene.h"
#include "traces/error.h"
#include "workloads/scene.h"

namespace rtsim::app {
namespace {

constexpr double kTargetRatio = 3.0;

struct BenchOptions {
  std::string scene = RTSIM_SHARED_SCENES_DIR "/conference/conference.obj";
  size_t rays = 1000000;
  uint64_t seed = 1;
  int repeat = 3;
  BvhConfig bvh;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int run_bench(const BenchOptions& o) {
  std::string problem = validate(o.bvh);
  if (!problem.empty()) throw_input_error("bvh config", "", problem);
  reports::require_generated_ray_memory(o.rays, "--rays");
  if (!is_builtin_scene(o.scene) && !std::filesystem::exists(o.scene)) {
    fmt::print(stderr,
               "rtsim bench: scene file {} not found (the shared scenes are not on this "
               "machine?); pass --scene FILE or a built-in scene, e.g. --scene grid:300000\n",
               o.scene);
    return 2;
  }
  auto start = std::chrono::steady_clock::now();
  Scene scene = load_scene(o.scene);
  fmt::print("scene      {} ({} triangles, loaded in {:.2f} s)\n", scene.source,
             scene.triangle_count(), seconds_since(start));
  start = std::chrono::steady_clock::now();
  BvhImage image = build_bvh_image(flat_mesh(scene), o.bvh);
  double model_build = seconds_since(start);
  start = std::chrono::steady_clock::now();
  EmbreeScene embree(scene.mesh, 1);
  double embree_build = seconds_since(start);
  fmt::print("model      {}, {} nodes, built in {:.2f} s (Embree: {:.2f} s, 1 thread)\n",
             describe(o.bvh), image.node_count, model_build, embree_build);
  std::vector<Ray> rays = sample_diffuse_rays(scene.mesh, o.rays, o.seed);
  fmt::print("rays       {} diffuse-GI-like rays, seed {}, best of {} runs per side\n", rays.size(),
             o.seed, o.repeat);

  TraversalUnit model(image);
  TraversalState state;
  double model_time = 1e30, embree_time = 1e30;
  uint64_t model_hits = 0, embree_hits = 0;
  TraversalCounters counters;
  for (int run = 0; run < o.repeat; ++run) {
    // Model: the same traversal `rtsim verify` checks, access lists included.
    start = std::chrono::steady_clock::now();
    model_hits = 0;
    counters = {};
    for (const Ray& ray : rays) {
      model_hits += model.trace(state, ray).hit();
      counters += state.counters;
    }
    model_time = std::min(model_time, seconds_since(start));
    // Embree, single-threaded, one ray at a time.
    start = std::chrono::steady_clock::now();
    embree_hits = 0;
    for (const Ray& ray : rays) embree_hits += embree.trace(ray).hit();
    embree_time = std::min(embree_time, seconds_since(start));
  }
  double n = rays.empty() ? 1.0 : double(rays.size());
  fmt::print("per ray    trav_nodes {:.2f}  trav_leaves {:.2f}  trav_prims {:.2f}\n",
             counters.trav_nodes / n, counters.trav_leaves / n, counters.trav_prims / n);
  fmt::print("hits       model {}  embree {}\n", model_hits, embree_hits);
  fmt::print("model      {:.3f} s  ({:.2f} Mrays/s)\n", model_time, n / model_time / 1e6);
  fmt::print("embree     {:.3f} s  ({:.2f} Mrays/s)\n", embree_time, n / embree_time / 1e6);
  double ratio = model_time / embree_time;
  fmt::print("ratio      {:.2f}x Embree (target <= {:.0f}x: {})\n", ratio, kTargetRatio,
             ratio <= kTargetRatio ? "met" : "missed");
  return 0;
}

}  // namespace

void add_bench_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("bench", "Time the functional model against Embree");
  auto options = std::make_shared<BenchOptions>();
  cmd->add_option("--scene", options->scene, "Scene file or built-in scene")->capture_default_str();
  reports::add_generated_rays_option(*cmd, options->rays, "Number of rays");
  cmd->add_option("--seed", options->seed, "Seed of the ray sampler")
      ->check(reports::non_negative())
      ->capture_default_str();
  cmd->add_option("--repeat", options->repeat, "Runs per side; the fastest counts")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  add_bvh_options(*cmd, options->bvh);
  cmd->callback([options, &exit_code] { exit_code = run_bench(*options); });
}

}  // namespace rtsim::app
