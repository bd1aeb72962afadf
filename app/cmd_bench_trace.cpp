// rtsim bench-trace WORKLOAD: how fast `rtsim trace` generates a workload's rays on one core,
// next to its reference, Embree alone tracing the same rays on one core in the same process.
// The speed goal (workloads/README.md): a 1920x1080 pica-pica frame of Sponza in under 10 s.
#include <fmt/core.h>
#include <unistd.h>

#include <cstdio>
#include <memory>
#include <optional>

#include "app/commands.h"
#include "reports/cli_options.h"
#include "traces/embree_scene.h"
#include "traces/error.h"
#include "traces/host_clock.h"
#include "traces/stream.h"
#include "workloads/pipeline/summary.h"
#include "workloads/pipeline/trace.h"
#include "workloads/scene.h"

namespace rtsim::app {
namespace {

struct BenchArgs {
  std::string workload, resolution, keep;
  uint32_t frames = 0;
  double goal = 10.0;
};

// Seconds for one thread of Embree to trace every ray of the stream (reading excluded).
double embree_reference(const std::string& stream, const Scene& scene, uint64_t& rays) {
  std::unique_ptr<EmbreeScene> embree = embree_scene(scene, 1);
  RayStreamReader reader(stream);
  std::vector<Ray> batch;
  double seconds = 0.0;
  uint64_t hits = 0;
  rays = 0;
  while (reader.next_batch(batch, 1u << 16) > 0) {
    double start = wall_seconds();
    for (const Ray& ray : batch) hits += embree->trace(ray).hit() ? 1 : 0;
    seconds += wall_seconds() - start;
    rays += batch.size();
  }
  return hits > rays ? 0.0 : seconds;  // hits keeps the loop from being optimised away
}

void run_bench(const BenchArgs& a) {
  pipeline::WorkloadSpec spec = pipeline::load_workload(a.workload);
  pipeline::apply_overrides(spec, pipeline::make_overrides({a.resolution, a.frames}));
  std::string stream =
      a.keep.empty() ? fmt::format("/tmp/rtsim-bench-trace-{}.rays", getpid()) : a.keep;
  pipeline::TraceOptions options;
  options.output = stream;
  options.generator = "rtsim " RTSIM_VERSION;
  options.embree_threads = 1;
  double start = wall_seconds();
  double cpu_start = cpu_seconds();
  pipeline::TraceResult result = pipeline::trace_workload(spec, options);
  double total = wall_seconds() - start, cpu = cpu_seconds() - cpu_start;
  const pipeline::RunSummary& s = result.summary;
  uint64_t rays = s.total_rays();
  fmt::print("{}", pipeline::format_summary(s));
  fmt::print("bench-trace {}: {}x{}, {} frame{}, one thread\n", s.workload, s.width, s.height,
             s.frames, s.frames == 1 ? "" : "s");
  fmt::print("  load scene        {:8.3f} s\n", s.load_seconds);
  fmt::print("  build Embree BVH  {:8.3f} s\n", s.build_seconds);
  fmt::print("  passes + write    {:8.3f} s  {:.2f} Mrays/s\n", s.trace_seconds,
             rays / s.trace_seconds * 1e-6);
  fmt::print("  total             {:8.3f} s  {} rays, {:.2f} Mrays/s\n", total, rays,
             rays / total * 1e-6);
  fmt::print("  CPU time          {:8.3f} s  goal < {:g} s per frame on one core: {}\n", cpu,
             a.goal, cpu / s.frames < a.goal ? "met" : "MISSED");
  Scene scene = load_scene(spec.scene);
  uint64_t read = 0;
  double reference = embree_reference(stream, scene, read);
  fmt::print(
      "  reference: Embree alone traces the same {} rays in {:.3f} s ({:.2f} Mrays/s); "
      "trace / Embree = {:.2f}x\n",
      read, reference, read / reference * 1e-6, s.trace_seconds / reference);
  if (a.keep.empty()) std::remove(stream.c_str());
}

}  // namespace

void add_bench_trace_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "bench-trace", "Time ray generation of a workload on one core against Embree alone");
  auto a = std::make_shared<BenchArgs>();
  cmd->add_option("workload", a->workload, "Workload spec (.toml) or built-in scene")->required();
  cmd->add_option("--resolution", a->resolution, "Image size WxH (overrides the spec)");
  cmd->add_option("--frames", a->frames, "Frames (overrides the spec)")
      ->check(reports::frame_range());
  cmd->add_option("--keep", a->keep, "Keep the stream at this path (default: a temp file)");
  cmd->add_option("--goal", a->goal, "Seconds per frame to compare against")->capture_default_str();
  cmd->callback([a, &exit_code] {
    run_bench(*a);
    exit_code = 0;
  });
}

}  // namespace rtsim::app
