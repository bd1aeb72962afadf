// rtsim sim STREAM --config HW.toml [--set key=value]... -o DIR [--no-verify]: runs the
// cycle-approximate model of the RT hardware over a ray stream and writes DIR/stats.json,
// DIR/config.toml (the resolved config) and per-pixel buffers. Every ray's answer is checked
// against Embree unless --no-verify; exit 1 if a mismatch is unexplained or the model stalls.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <fmt/core.h>
#include <fmt/ranges.h>

#include "app/commands.h"
#include "reports/cli_options.h"
#include "reports/phase_progress.h"
#include "reports/report_writer.h"
#include "reports/run_job.h"
#include "reports/sim_folder.h"
#include "model/config/config_presets.h"
#include "model/config/hw_config.h"
#include "model/sc/sim_report.h"
#include "model/sc/stream_sim.h"
#include "traces/error.h"
#include "traces/output_file.h"
#include "traces/text_table.h"
#include "workloads/scene.h"

namespace rtsim::app {
namespace {

struct SimOptions {
  std::string stream, config, output, scene;
  std::vector<std::string> sets, ray_types;
  bool no_verify = false, quiet = false, list_keys = false;
};

// The command line, as the report of the folder shows it.
std::string command_line(const SimOptions& o) {
  std::string out = "rtsim sim " + o.stream;
  if (!o.config.empty()) out += " --config " + o.config;
  for (const std::string& s : o.sets) out += " --set " + s;
  if (!o.scene.empty()) out += " --scene " + o.scene;
  if (!o.ray_types.empty()) out += fmt::format(" --ray-types {}", fmt::join(o.ray_types, ","));
  if (o.no_verify) out += " --no-verify";
  return out + " -o " + o.output;
}

// A Markdown table, as model/SIM-REFERENCE.md shows it.
void print_keys() {
  fmt::print("| key | type | default | unit | description |\n|---|---|---|---|---|\n");
  for (const HwConfigKey& k : hw_config_keys())
    fmt::print("| `{}` | {} | {} | {} | {} |\n", k.key, k.type, k.default_value, k.unit,
               k.description);
}

void print_summary(const nlohmann::ordered_json& doc) {
  const auto& s = doc["summary"];
  fmt::print("cycles     {}  ({:.3f} rays/cycle, {:.1f} MRays/s at {} GHz)\n",
             whole_number(s["cycles"].get<uint64_t>()), s["rays_per_cycle"].get<double>(),
             s["mrays_per_second"].get<double>(), s["clock_ghz"].get<double>());
  if (s["warmup_rays"] != 0 || s["warmup_frames"] != 0)
    fmt::print("warm-up    {} rays, {} frames: stats from cycle {} on\n",
               whole_number(s["warmup_rays"].get<uint64_t>()), s["warmup_frames"].get<uint64_t>(),
               whole_number(s["measured_from_cycle"].get<uint64_t>()));
  for (const auto& f : doc["frames"])
    fmt::print(
        "frame {:<4} {:>9} rays  {:>10} cycles  L2 hit rate {:.1f}%  compulsory {:.1f}%  DRAM "
        "{:.0f} B/ray\n",
        f["frame"].get<uint64_t>(), whole_number(f["rays"].get<double>()),
        whole_number(f["cycles"].get<double>()), 100 * f["memory"]["l2_hit_rate"].get<double>(),
        100 * f["memory"]["l2_compulsory_share"].get<double>(),
        f["memory"]["dram_bytes_per_ray"].get<double>());
  for (const auto& [type, t] : doc["ray_types"].items()) {
    const auto& warps = t["warp_latency_cycles"];
    std::string warp_p99 = warps["warps"] == 0 ? "-" : warps["p99"].dump();
    fmt::print(
        "{:<12} {:>9} rays  latency p50/p95/p99 {}/{}/{}  warp p99 {}  nodes {:.1f}  tris {:.1f}  "
        "L1 hit rate {:.1f}%  L2 hit rate {:.1f}%  DRAM {:.0f} B/ray\n",
        type, whole_number(t["rays"].get<uint64_t>()), t["latency_cycles"]["p50"].get<uint64_t>(),
        t["latency_cycles"]["p95"].get<uint64_t>(), t["latency_cycles"]["p99"].get<uint64_t>(),
        warp_p99, t["nodes_per_ray"].get<double>(), t["triangles_per_ray"].get<double>(),
        100 * t["l1_hit_rate"].get<double>(), 100 * t["l2_hit_rate"].get<double>(),
        t["dram_bytes_per_ray"].get<double>());
  }
  if (doc["bottleneck"]["text"].is_string())
    fmt::print("limit      {}\n", doc["bottleneck"]["text"].get<std::string>());
  const auto& m = doc["memory"];
  auto percent = [](const nlohmann::ordered_json& v) {
    return v.is_null() ? std::string("n/a") : fmt::format("{:.1f}%", 100 * v.get<double>());
  };
  if (m["levels"].size() != 2) {  // every level
    std::string levels;
    for (const auto& l : m["levels"])
      levels += fmt::format("{} hit rate {} served {} compulsory {}  ",
                            l["name"].get<std::string>(), percent(l["hit_rate"]),
                            percent(l["served_rate"]), percent(l["compulsory_share"]));
    fmt::print(
        "memory     {}(served: hits and merges into misses in flight; compulsory: share "
        "of misses)\n",
        levels);
  } else {
    fmt::print(
        "memory     L1 hit rate {} served {} compulsory {}  L2 hit rate {} served {} compulsory {} "
        " "
        "(served: hits and merges into misses in flight; compulsory: share of misses)\n",
        percent(m["l1_hit_rate"]), percent(m["l1_served_rate"]), percent(m["l1_compulsory_share"]),
        percent(m["l2_hit_rate"]), percent(m["l2_served_rate"]), percent(m["l2_compulsory_share"]));
  }
  const auto& u = doc["utilisation"]["mean"];
  fmt::print(
      "busy       box {:.1f}%  triangle {:.1f}%  control {:.1f}%  ray slots {:.1f}%  "
      "DRAM {:.1f}%\n",
      100 * u["box"].get<double>(), 100 * u["triangle"].get<double>(),
      100 * u["control"].get<double>(), 100 * u["ray_slots"].get<double>(),
      100 * doc["utilisation"]["dram"].get<double>());
  if (!doc["shader"].is_null()) fmt::print("{}\n", shader_summary_line(doc["shader"]));
  fmt::print("{}\n", energy_summary_line(doc["energy"]));
  const auto& c = doc["coherence"];
  std::string coherence;
  if (!c["simd_efficiency"].is_null())
    coherence = fmt::format("SIMD efficiency {:.1f}%  distinct nodes per warp step {:.2f}  ",
                            100 * c["simd_efficiency"].get<double>(),
                            c["distinct_nodes_per_warp_step"].get<double>());
  if (!c["rays_per_treelet_visit"].is_null())
    coherence = fmt::format("rays per treelet visit {:.1f}  queued rays mean {:.0f} max {:.0f}  ",
                            c["rays_per_treelet_visit"].get<double>(),
                            c["treelet_queue_mean_rays"].get<double>(),
                            c["treelet_queue_max_rays"].get<double>());
  fmt::print("coherence  {}stack spills per ray {:.2f}\n", coherence,
             doc["stack"]["spills_per_ray"].get<double>());
}

}  // namespace

std::string shader_summary_line(const nlohmann::ordered_json& sh) {
  double busy = std::max(sh["busy_cycles"].get<double>(), 1.0);
  auto share = [&](const char* key) { return 100 * sh[key].get<double>() / busy; };
  return fmt::format(
      "shader     SM schedulers {:.1f}% busy ({:.1f} cycles a ray: raygen {:.0f}%, hit {:.0f}%, "
      "miss {:.0f}%)  rays reach their unit {:.1f} cycles later  waited for warp slots {:.0f} "
      "cycles  shading reads {:.2f} DRAM B/ray",
      100 * sh["utilisation"].get<double>(), sh["busy_cycles_per_ray"].get<double>(),
      share("raygen_cycles"), share("hit_cycles"), share("miss_cycles"),
      sh["mean_trace_delay"].get<double>(), sh["slot_wait_cycles"].get<double>(),
      sh["reads_dram_bytes_per_ray"].get<double>());
}

std::string energy_summary_line(const nlohmann::ordered_json& e) {
  // The three structures that took the most energy, dynamic and static.
  std::vector<std::pair<double, std::string>> shares;
  double total = std::max(e["total_nj"].get<double>(), 1e-30);
  for (const auto& [name, s] : e["structures"].items())
    shares.emplace_back((s["dynamic_nj"].get<double>() + s["static_nj"].get<double>()) / total,
                        name);
  std::sort(shares.rbegin(), shares.rend());
  std::string most;
  for (size_t i = 0; i < std::min<size_t>(3, shares.size()); ++i)
    most += fmt::format("{}{} {:.0f}%", i ? ", " : "", shares[i].second, 100 * shares[i].first);
  const auto& per_ray = e["nj_per_ray"];  // null without rays
  return fmt::format(
      "energy     {} nJ/ray  {:.4g} MRays/J  {:.3g} W  (static {:.0f}%; most: {})  area {:.3g} "
      "mm² (SRAM {:.3g}) at {}",
      per_ray.is_null() ? "n/a" : fmt::format("{:.3g}", per_ray.get<double>()),
      e["mrays_per_joule"].get<double>(), e["power_w"].get<double>(),
      100 * e["static_nj"].get<double>() / total, most, e["area_mm2"].get<double>(),
      e["sram_area_mm2"].get<double>(), e["node"].get<std::string>());
}

namespace {

int run_sim(const SimOptions& o) {
  if (o.list_keys) {
    print_keys();
    return 0;
  }
  if (o.stream.empty() || o.output.empty())
    throw InputError("sim: STREAM and -o DIR are required (or --list-keys)");
  std::vector<NamedPath> outputs;
  for (const std::string& file : sim_result_files(o.output)) outputs.push_back({"-o", file});
  for (const char* name : {"fidelity.json", "sim.json"})
    outputs.push_back({"-o", o.output + "/" + name});
  refuse_overwriting({{"the stream", o.stream},
                      {"--config", hw_config_path(o.config)},
                      {"--scene", is_builtin_scene(o.scene) ? "" : o.scene}},
                     outputs);
  reports::RunJob job;
  job.stream = o.stream;
  job.config = load_hw_config(o.config, o.sets);
  job.verify = !o.no_verify;
  job.output = o.output;
  job.progress = !o.quiet;
  job.scene = o.scene;
  job.ray_types = o.ray_types;
  reports::TraceOutcome trace = reports::read_stream_trace(o.stream);
  RayStreamReader reader(o.stream);
  RayTypeMask types = reports::selected_ray_types(o.ray_types, reader.header(), "sim", o.stream);
  const HwConfig& config = job.config;
  if (!o.quiet) {
    fmt::print(
        "sim        {} rays{} of {} on '{}' ({}, {} RT units, {})\n",
        whole_number(uint64_t(rays_of(reader.header(), types))),
        o.ray_types.empty() ? "" : " (" + fmt::format("{}", fmt::join(o.ray_types, ", ")) + ")",
        o.stream, config.name, traversal_mode_name(config.rt.mode), config.rt_units,
        describe(config.bvh));
    if (o.config.empty())
      fmt::print(
          "config     built in (no --config): the defaults rtsim sim --list-keys shows; presets "
          "are in configs/\n");
  }
  std::fflush(stdout);  // the header before the progress lines, also in a pipe
  reports::clear_sim_folder_report(o.output);
  reports::RunResult result = reports::run_job(job);
  if (result.stalled) {
    fmt::print(stderr, "rtsim: stall: {}", result.stall_message);
    return 1;
  }
  reports::write_sim_run(o.output, {command_line(o), o.config, o.sets}, trace, result);
  const nlohmann::ordered_json& doc = result.stats;
  if (!o.quiet) {
    print_summary(doc);
    fmt::print(
        "host       {:.2f} s, {} rays/s; results in {} (rtsim report {} writes its "
        "report)\n",
        doc["host"]["seconds"].get<double>(),
        whole_number(doc["host"]["rays_per_second"].get<double>()), o.output, o.output);
  }
  const auto& v = doc["verify"];
  if (v.contains("skipped")) return 0;
  uint64_t unexplained = v["unexplained"].get<uint64_t>();
  if (!o.quiet || unexplained)
    fmt::print("verify     {} rays against Embree: {} mismatches, {} unexplained\n",
               whole_number(v["rays"].get<uint64_t>()),
               whole_number(v["mismatches"].get<uint64_t>()), whole_number(unexplained));
  for (const Mismatch& m : result.unexplained)
    fmt::print("unexplained ray {} ({}): Embree triangle {} t={}, model triangle {} t={}\n",
               m.index, ray_type_name(m.ray.type), m.embree.prim, m.embree.t, m.model_prim,
               m.model.t);
  return unexplained > 0 ? 1 : 0;
}

}  // namespace

void add_sim_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("sim", "Run the cycle-approximate hardware model on a stream");
  auto options = std::make_shared<SimOptions>();
  cmd->add_option("stream", options->stream, "Ray stream (.rays)");
  cmd->add_option("--config", options->config, "Hardware config: " + kConfigForms);
  reports::add_config_overrides(*cmd, options->sets);
  cmd->add_option("-o,--output", options->output, "Folder for stats.json, config.toml, pixels");
  cmd->add_option("--scene", options->scene, "Scene file or built-in (default: stream header)");
  cmd->add_option("--ray-types", options->ray_types,
                  "Simulate only these ray types of the stream: --ray-types shadow,diffuse_gi")
      ->delimiter(',')
      ->allow_extra_args(false);
  cmd->add_flag("--no-verify", options->no_verify, "Skip the check of every ray against Embree");
  cmd->add_flag("-q,--quiet", options->quiet, "Print nothing but errors");
  cmd->add_flag("--list-keys", options->list_keys, "List every hardware config key and exit");
  cmd->callback([options, &exit_code] { exit_code = run_sim(*options); });
}

}  // namespace rtsim::app
