// rtsim speed-vs-error WORKLOAD --config HW.toml: runs the full cycle-approximate model once as
// the reference, then each faster fidelity level (functional, cache-level, sampled at each
// rate) on the same stream and config, each in its own child process, and prints their host
// time, speed-up and error in cycles, DRAM bytes and hit rates. With -o DIR it also writes
// speed_vs_error.{json,csv,md} and the chart speed_vs_error.png.
#include <unistd.h>

#include <filesystem>
#include <memory>

#include <fmt/core.h>

#include "app/commands.h"
#include "reports/phase_progress.h"
#include "model/config/hw_config.h"
#include "model/fidelity/level_runner.h"
#include "model/sc/sim_report.h"
#include "reports/charts.h"
#include "reports/cli_options.h"
#include "reports/speed_error.h"
#include "traces/output_file.h"
#include "traces/error.h"
#include "traces/text_table.h"
#include "workloads/scene.h"

namespace rtsim::app {
namespace {

struct SpeedErrorOptions {
  reports::TraceRequest workload;
  std::string from_trace, config, output;
  std::vector<std::string> sets;
  std::vector<uint32_t> rates{4, 8, 16, 32, 64};
  std::vector<std::string> levels{"functional", "cache", "sampled"};
  SamplingConfig sampling;
  std::vector<std::string> sample_methods{"scale-model"};
  std::vector<SampleMethod> methods;
  int repeat = 1;
  uint32_t seeds = 1;
  bool no_charts = false;
};

// The run with the least CPU time of `repeat` (host time is noisy; results are deterministic).
FidelityResult best_of(const SpeedErrorOptions& o, const LevelRequest& request,
                       const HwConfig& config, BvhView image, const std::string& stream) {
  FidelityResult best = run_level_in_child(request, config, image, stream);
  for (int i = 1; i < o.repeat; ++i) {
    FidelityResult again = run_level_in_child(request, config, image, stream);
    if (again.cpu_seconds < best.cpu_seconds) best = again;
  }
  return best;
}

std::vector<LevelRequest> requests(const SpeedErrorOptions& o) {
  std::vector<LevelRequest> out;
  for (const std::string& name : o.levels) {
    auto level = fidelity_level_from_name(name);
    if (!level || *level == FidelityLevel::Cycle)
      throw InputError("speed-vs-error: --levels: unknown level '" + name +
                       "' (functional, cache, sampled)");
    if (*level != FidelityLevel::Sampled) {
      out.push_back({*level, o.sampling});
      continue;
    }
    for (SampleMethod method : o.methods)
      for (uint32_t rate : o.rates) {
        LevelRequest r{FidelityLevel::Sampled, o.sampling};
        r.sampling.method = method;
        r.sampling.rate = rate;
        out.push_back(r);
      }
  }
  return out;
}

std::string label(const FidelityResult& r) {
  if (r.level != FidelityLevel::Sampled) return fidelity_level_name(r.level);
  bool scale_model = r.sample_method == sample_method_name(SampleMethod::ScaleModel);
  return fmt::format("{} 1/{}", scale_model ? "sampled" : r.sample_method, r.sample_rate);
}

int run_speed_error(const SpeedErrorOptions& o) {
  for (uint32_t rate : o.rates)
    if (rate < 2 || rate > 1024) throw InputError("speed-vs-error: --rates: 2 to 1024");
  HwConfig config = load_hw_config(o.config, o.sets);
  std::vector<LevelRequest> runs = requests(o);
  if (!o.output.empty()) {
    create_output_folder(o.output);
    lock_output_folder(o.output, "rtsim speed-vs-error");
  }
  std::string work = o.output.empty() ? (std::filesystem::temp_directory_path() /
                                         ("rtsim-speed-vs-error-" + std::to_string(getpid())))
                                            .string()
                                      : o.output;
  reports::TraceOutcome trace = o.from_trace.empty()
                                    ? reports::trace_into(o.workload, work + "/trace", false)
                                    : reports::read_trace_dir(o.from_trace);
  uint64_t rays = trace.summary["rays"].get<uint64_t>();
  for (const LevelRequest& r : runs)
    if (r.level == FidelityLevel::Sampled && rays < 2ull * r.sampling.rate)
      throw_input_error(trace.stream, "",
                        fmt::format("{} rays, too few to sample 1 in {} (at least {} needed)", rays,
                                    r.sampling.rate, 2 * r.sampling.rate));
  Scene scene = load_stream_scene(trace.stream, RayStreamReader(trace.stream).header());
  TwoLevelBvh bvh = reports::build_scene_bvh(scene, config.bvh, false);
  BvhView image(bvh);
  fmt::print("reference  full cycle-approximate model, {} rays, '{}'\n",
             whole_number(uint64_t(rays)), config.name);
  reports::LevelRun reference{
      "cycle", best_of(o, {FidelityLevel::Cycle, {}}, config, image, trace.stream), {}};
  std::vector<reports::LevelRun> results;
  for (const LevelRequest& request : runs) {
    FidelityResult r = best_of(o, request, config, image, trace.stream);
    fmt::print("level      {:<14} {:.2f} s CPU\n", label(r), r.cpu_seconds);
    reports::LevelRun run{label(r), r, {}};
    for (uint32_t s = 1; s < o.seeds && request.level == FidelityLevel::Sampled; ++s) {
      LevelRequest other = request;
      other.sampling.seed = request.sampling.seed + s;
      run.other_seeds.push_back(best_of(o, other, config, image, trace.stream));
    }
    results.push_back(run);
  }
  nlohmann::ordered_json context = {{"workload", trace.summary["workload"]},
                                    {"scene", trace.summary["scene"]},
                                    {"triangles", trace.summary["triangles"]},
                                    {"rays", trace.summary["rays"]},
                                    {"width", trace.summary["width"]},
                                    {"height", trace.summary["height"]},
                                    {"config", config.name},
                                    {"config_file", o.config},
                                    {"sets", o.sets},
                                    {"repeat", o.repeat},
                                    {"seeds", o.seeds}};
  nlohmann::ordered_json doc = reports::speed_error_json(reference, results, context);
  fmt::print("\n{}", reports::speed_error_table(doc, false));
  if (o.output.empty()) {
    std::filesystem::remove_all(work);
    return 0;
  }
  std::filesystem::create_directories(o.output);
  write_file_atomic(o.output + "/speed_vs_error.json", doc.dump(2) + "\n");
  write_file_atomic(o.output + "/speed_vs_error.csv", reports::speed_error_csv(doc));
  write_file_atomic(o.output + "/speed_vs_error.md", reports::speed_error_markdown(doc));
  int exit_code = 0;
  if (!o.no_charts)
    exit_code = reports::chart_exit_code(reports::run_chart_script(
        "speed_error_chart.py", {o.output + "/speed_vs_error.json", o.output}));
  fmt::print("\nresults in {}\n", o.output);
  return exit_code;
}

}  // namespace

void add_speed_vs_error_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "speed-vs-error", "Host time and error of each fidelity level against the full model");
  auto o = std::make_shared<SpeedErrorOptions>();
  cmd->add_option("workload", o->workload.workload, "Workload spec (.toml) or built-in scene");
  reports::add_workload_options(*cmd, o->workload);
  cmd->add_option("--from-trace", o->from_trace, "Use this trace folder (of rtsim run)");
  cmd->add_option("--config", o->config, "Hardware config: " + kConfigForms);
  cmd->add_option("--set", o->sets, "Override a config key")->allow_extra_args(false);
  cmd->add_option("--rates", o->rates, "Sample rates: 1 in N rays")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--levels", o->levels, "Levels to compare with the full model")
      ->delimiter(',')
      ->capture_default_str();
  reports::add_sampling_options(*cmd, o->sampling, o->sample_methods, true);
  cmd->add_option("--repeat", o->repeat, "Runs per level; the one with the least CPU time counts")
      ->check(CLI::Range(1, 20))
      ->capture_default_str();
  cmd->add_option("--seeds", o->seeds, "Sampled level: seeds per rate (rms error over them)")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  cmd->add_option("-o,--output", o->output, "Folder for the trace, JSON, CSV, Markdown, chart");
  cmd->add_flag("--no-charts", o->no_charts, "Skip the chart");
  cmd->callback([o, cmd, &exit_code] {
    reports::refuse_workload_with_trace(*cmd, o->from_trace);
    if (o->workload.workload.empty() && o->from_trace.empty())
      throw InputError("speed-vs-error: a workload (spec or built-in scene) or --from-trace");
    o->methods = reports::sampling_methods(*cmd, o->sample_methods);
    exit_code = run_speed_error(*o);
  });
}

}  // namespace rtsim::app
