// rtsim bench-sim: how fast the cycle-approximate model simulates, against Embree's
// single-threaded time on the same rays (default: 1M diffuse-GI-like rays on Conference; or
// --stream FILE, read in constant memory), best of --repeat runs per side by CPU time. Embree
// runs in this process; each simulation runs in a forked child (SystemC allows one
// elaboration per process), which reports its time and peak memory. --compare-exact also runs the
// config with sim.quantum_cycles = 1 (events in exact global order) and prints how far the faster
// run's cycles are from it.
// --write-stream FILE writes the generated rays as a stream (e.g. 5M rays for the memory check).
#include <sys/resource.h>

#include <cstdlib>
#include <filesystem>
#include <memory>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "reports/cli_options.h"
#include "model/config/config_presets.h"
#include "model/config/hw_config.h"
#include "model/sc/fork_run.h"
#include "model/sc/rt_simulator.h"
#include "model/verify/ray_samples.h"
#include "reports/phase_progress.h"
#include "traces/embree_scene.h"
#include "traces/error.h"
#include "traces/host_clock.h"
#include "traces/output_file.h"
#include "workloads/scene.h"

namespace rtsim::app {
namespace {

struct BenchSimOptions {
  std::string scene = RTSIM_SHARED_SCENES_DIR "/conference/conference.obj";
  std::string stream, write_stream, config;
  std::vector<std::string> sets;
  size_t rays = 1000000;
  uint64_t seed = 1;
  int repeat = 3;
  bool compare_exact = false, no_embree = false;
};

double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

// Feeds rays from memory or from the stream file (reopened per pass).
std::unique_ptr<RaySource> open_source(const BenchSimOptions& o, const std::vector<Ray>& rays,
                                       std::unique_ptr<RayStreamReader>& reader) {
  if (o.stream.empty()) return std::make_unique<VectorRaySource>(rays);
  reader = std::make_unique<RayStreamReader>(o.stream);
  return std::make_unique<StreamRaySource>(*reader);
}

struct Timing {
  double wall = 1e30, cpu = 1e30;
};

// Embree on one thread over what the simulation traverses: the flat mesh, or the instances.
Timing time_embree(const BenchSimOptions& o, const Scene& scene, bool instances,
                   const std::vector<Ray>& rays, uint64_t& count) {
  std::unique_ptr<EmbreeScene> reference =
      instances ? std::make_unique<EmbreeScene>(scene.instanced, scene.instance_settings, 1)
                : std::make_unique<EmbreeScene>(scene.mesh, 1);
  const EmbreeScene& embree = *reference;
  Timing best;
  for (int run = 0; run < o.repeat; ++run) {
    std::unique_ptr<RayStreamReader> reader;
    auto source = open_source(o, rays, reader);
    Ray ray;
    count = 0;
    double start = wall_seconds();
    double cpu = cpu_seconds();
    for (; source->next(ray); ++count) embree.trace(ray);
    best.cpu = std::min(best.cpu, cpu_seconds() - cpu);
    best.wall = std::min(best.wall, wall_seconds() - start);
  }
  return best;
}

// One simulation in a child process; returns its figures as JSON.
nlohmann::json simulate(const BenchSimOptions& o, const HwConfig& config, BvhView image,
                        const std::vector<Ray>& rays) {
  std::string text = run_in_child([&] {
    std::unique_ptr<RayStreamReader> reader;
    auto source = open_source(o, rays, reader);
    RtSimulator sim(config, image, *source);
    double start = wall_seconds();
    double cpu = cpu_seconds();
    sim.run();
    cpu = cpu_seconds() - cpu;
    double seconds = wall_seconds() - start;
    StatsRegistry stats;
    sim.report(stats);
    const std::string shared = "mem." + last_level(config).name;  // the level above DRAM
    nlohmann::json out = {
        {"seconds", seconds},
        {"cpu_seconds", cpu},
        {"rays", sim.rays()},
        {"cycles", sim.cycles()},
        {"dram_bytes", stats.value("dram.bytes")},
        {"l2_requests", stats.value(shared + ".accesses") + stats.value(shared + ".writes")},
        {"peak_rss_mib", peak_rss_mib()}};
    return out.dump();
  });
  return nlohmann::json::parse(text);
}

void write_stream(const BenchSimOptions& o, const Scene& scene, const std::vector<Ray>& rays) {
  StreamHeader header;
  header.scene_source = scene.source;
  header.scene_fingerprint = scene.fingerprint;
  header.workload = "bench-sim diffuse";
  header.generator = "rtsim bench-sim";
  header.seed = o.seed;
  RayStreamWriter writer(o.write_stream, header);
  for (const Ray& ray : rays) writer.write(ray);
  writer.finish();
  fmt::print("wrote      {} rays to {}\n", rays.size(), o.write_stream);
}

int run_bench_sim(const BenchSimOptions& o) {
  if (!is_builtin_scene(o.scene) && !std::filesystem::exists(o.scene) && o.stream.empty()) {
    fmt::print(stderr,
               "rtsim bench-sim: scene {} not found (no shared scenes here?); pass "
               "--scene FILE or a built-in, e.g. --scene grid:300000\n",
               o.scene);
    return 2;
  }
  if (o.stream.empty()) reports::require_generated_ray_memory(o.rays, "--rays");
  refuse_overwriting({{"--stream", o.stream},
                      {"--config", hw_config_path(o.config)},
                      {"--scene", is_builtin_scene(o.scene) ? "" : o.scene}},
                     {{"--write-stream", o.write_stream}});
  HwConfig config = load_hw_config(o.config, o.sets);
  // A stream's scene as it was traced: its fingerprint checked, its instance settings applied.
  Scene scene = o.stream.empty() ? load_scene(o.scene)
                                 : load_stream_scene(o.stream, RayStreamReader(o.stream).header());
  TwoLevelBvh image = reports::build_scene_bvh(scene, config.bvh, true);
  bool two_levels = !image.bottom.empty();
  std::vector<Ray> rays;
  if (o.stream.empty()) rays = sample_diffuse_rays(scene.triangles(), o.rays, o.seed);
  if (!o.write_stream.empty()) {
    write_stream(o, scene, rays);
    return 0;
  }
  fmt::print("scene      {} ({} triangles), {}{}\n", scene.source, scene.triangle_count(),
             describe(config.bvh),
             two_levels
                 ? fmt::format(", two levels over {} instances of {} meshes",
                               scene.instanced.instances.size(), scene.instanced.meshes.size())
                 : "");
  fmt::print("config     {} ({}, {} RT units, quantum {} cycles)\n", config.name,
             traversal_mode_name(config.rt.mode), config.rt_units, config.sim.quantum_cycles);
  fmt::print("rays       {}\n",
             o.stream.empty() ? fmt::format("{} diffuse-GI-like, seed {}", rays.size(), o.seed)
                              : o.stream);
  uint64_t count = 0;
  Timing embree = o.no_embree ? Timing{} : time_embree(o, scene, two_levels, rays, count);
  if (!o.no_embree)
    fmt::print("embree     {:.3f} s wall, {:.3f} s CPU, 1 thread, best of {} ({:.2f} MRays/s)\n",
               embree.wall, embree.cpu, o.repeat, count / embree.cpu / 1e6);
  // Best of `repeat` runs, by CPU time, as for Embree.
  nlohmann::json sim;
  for (int run = 0; run < o.repeat; ++run) {
    nlohmann::json next = simulate(o, config, image, rays);
    if (run == 0 || next["cpu_seconds"].get<double>() < sim["cpu_seconds"].get<double>())
      sim = next;
  }
  double seconds = sim["seconds"].get<double>(), cpu = sim["cpu_seconds"].get<double>();
  double n = sim["rays"].get<double>();
  fmt::print(
      "sim        {:.0f} rays, {:.3f} s wall, {:.3f} s CPU ({:.0f} rays per CPU second), {} "
      "cycles, "
      "{:.0f} DRAM B/ray, {:.0f} L2 requests ({:.1f}/ray), child peak memory {:.0f} MiB\n",
      n, seconds, cpu, n / cpu, sim["cycles"].get<uint64_t>(), sim["dram_bytes"].get<double>() / n,
      sim["l2_requests"].get<double>(), sim["l2_requests"].get<double>() / n,
      sim["peak_rss_mib"].get<double>());
  if (!o.no_embree)
    fmt::print(
        "ratio      simulation / Embree = {:.1f}x in CPU time, {:.1f}x in wall time "
        "(goal: within {}x)\n",
        cpu / embree.cpu, seconds / embree.wall,
        config.rt.mode == TraversalMode::Treelet ? 40 : 20);  // queues do more per ray
  if (o.compare_exact) {
    HwConfig exact = config;
    exact.sim.quantum_cycles = 1;
    nlohmann::json ref = simulate(o, exact, image, rays);
    double ref_cycles = ref["cycles"].get<double>();
    fmt::print(
        "exact      quantum 1: {:.3f} s, {} cycles; quantum {} is {:+.2f}% in cycles, "
        "{:+.2f}% in DRAM bytes, {:.2f}x faster\n",
        ref["seconds"].get<double>(), ref["cycles"].get<uint64_t>(), config.sim.quantum_cycles,
        100 * (sim["cycles"].get<double>() / ref_cycles - 1),
        100 * (sim["dram_bytes"].get<double>() / ref["dram_bytes"].get<double>() - 1),
        ref["seconds"].get<double>() / seconds);
  }
  return 0;
}

}  // namespace

void add_bench_sim_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("bench-sim", "Time the cycle-approximate model against Embree");
  auto o = std::make_shared<BenchSimOptions>();
  cmd->add_option("--scene", o->scene, "Scene file or built-in scene")->capture_default_str();
  reports::add_generated_rays_option(*cmd, o->rays, "Diffuse-GI-like rays to generate");
  cmd->add_option("--seed", o->seed, "Seed of the ray sampler")
      ->check(reports::non_negative())
      ->capture_default_str();
  cmd->add_option("--stream", o->stream, "Simulate this stream instead (constant memory)");
  cmd->add_option("--config", o->config, "Hardware config: " + kConfigForms);
  cmd->add_option("--set", o->sets, "Override a config key")->allow_extra_args(false);
  cmd->add_option("--repeat", o->repeat, "Runs per side; the fastest (CPU time) counts")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  cmd->add_flag("--compare-exact", o->compare_exact, "Also run with quantum 1 and compare");
  cmd->add_flag("--no-embree", o->no_embree, "Skip the Embree timing");
  cmd->add_option("--write-stream", o->write_stream, "Write the generated rays here and exit");
  cmd->callback([o, &exit_code] { exit_code = run_bench_sim(*o); });
}

}  // namespace rtsim::app
