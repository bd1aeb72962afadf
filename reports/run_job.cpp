#include "reports/run_job.h"
#include "reports/phase_progress.h"

#include <cstdlib>
#include <filesystem>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "model/fidelity/cycle_level.h"
#include "model/sc/sim_report.h"
#include "model/sc/stream_sim.h"
#include "reports/run_collector.h"
#include "traces/error.h"
#include "traces/output_file.h"
#include "workloads/scene.h"

namespace rtsim::reports {
namespace {

RunResult run_cycle(const RunJob& job, const Scene& scene, BvhView bvh) {
  RayStreamReader reader(job.stream);
  StreamHeader header = reader.header();
  RayTypeMask types = selected_ray_types(job.ray_types, header, "sim", job.stream);
  StreamSim sim(job.config, bvh, scene.mesh, scene.instanced, reader, job.verify, job.progress,
                types);
  RunCollector collector;
  sim.listen(&collector);
  HostTimer timer;
  RunResult result;
  try {
    sim.run();
  } catch (const SimStallError& e) {
    result.stalled = true;
    result.stall_message = e.what();
    return result;
  }
  result.fidelity = cycle_level_result(sim.simulator());
  timer.stop(result.fidelity);
  SimRunInfo info{job.stream,   header, bvh, sim.verify_report(), result.fidelity.host_seconds,
                  job.ray_types};
  result.stats = write_sim_results(job.output, sim.simulator(), info);
  result.collected = collector.to_json();
  if (sim.verify_report()) result.unexplained = sim.verify_report()->unexplained_examples;
  write_file_atomic(job.output + "/fidelity.json", result.fidelity.to_json().dump(2) + "\n");
  return result;
}

}  // namespace

RayTypeMask selected_ray_types(const std::vector<std::string>& names, const StreamHeader& header,
                               const std::string& what, const std::string& stream) {
  if (names.empty()) return kAllRayTypes;
  RayTypeMask mask = 0;
  for (const std::string& name : names) {
    std::optional<RayType> type = ray_type_from_name(name);
    if (!type) {
      std::string known;
      for (int t = 0; t < kRayTypeCount; ++t)
        known += std::string(t ? ", " : "") + ray_type_name(RayType(t));
      throw InputError(
          fmt::format("{}: --ray-types: unknown ray type '{}' (one of {})", what, name, known));
    }
    mask |= ray_type_bit(*type);
  }
  if (rays_of(header, mask) == 0)
    throw InputError(
        fmt::format("{}: {} has no rays of the types {}", what, stream, fmt::join(names, ", ")));
  return mask;
}

RunResult run_job(const RunJob& job) {
  create_output_folder(job.output);
  Scene scene = load_stream_scene(job.stream, RayStreamReader(job.stream).header(), job.scene);
  TwoLevelBvh bvh = build_scene_bvh(scene, job.config.bvh, !job.progress);
  if (job.level.level == FidelityLevel::Cycle) return run_cycle(job, scene, bvh);
  RunResult result;
  result.fidelity = run_level(job.level, job.config, bvh, job.stream);
  write_file_atomic(job.output + "/config.toml", resolved_toml(job.config));
  write_file_atomic(job.output + "/fidelity.json", result.fidelity.to_json().dump(2) + "\n");
  return result;
}

}  // namespace rtsim::reports
