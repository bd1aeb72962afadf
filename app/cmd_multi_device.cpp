// rtsim multi-device WORKLOAD_OR_STREAM -o DIR: M devices render every frame together (no
// alternate-frame rendering), once per split strategy (static, balanced, cost, current; Harada &
// Fujita 2014), with SEED's mGPU flow as the frame's cost model, and one device alone for the
// speed-up. Devices come from a device set (--devices-file configs/multi/*.toml) or from
// --config HW.toml --devices M, or one --device-config per device. A workload spec or scene is
// traced first into DIR/workload.rays. Writes DIR/report.json, report.md, frames.csv,
// devices.csv and chart.png, and prints the deviation figures. Keys and report:
// model/multi/README.md.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <thread>

#include <fmt/core.h>

#include "app/commands.h"
#include "reports/cli_options.h"
#include "model/multi/device_set.h"
#include "model/multi/multi_report.h"
#include "model/multi/multi_run.h"
#include "model/multi/multi_summary.h"
#include "model/multi/systemc_backend.h"
#include "reports/charts.h"
#include "traces/output_file.h"
#include "traces/error.h"
#include "workloads/pipeline/trace.h"
#include "workloads/scene.h"

namespace rtsim::app {
namespace {

struct MultiOptions {
  std::string input, output, devices_file, config, resolution;
  std::vector<std::string> device_configs, device_sets, hw_sets, split;
  uint32_t devices = 0, frames = 0, jobs = 0, warmup_frames = 0;
  uint64_t seed = 0;
  float orbit = 0;
  bool seed_set = false, orbit_set = false, warmup_set = false, importance = false;
  bool no_chart = false, quiet = false, list_keys = false;
};

void print_keys() {
  for (const ConfigKeyDoc& k : multi::device_set_keys())
    fmt::print("{:<28} {:<18} default {}{}\n    {}\n", k.key, k.type, k.default_value,
               k.unit.empty() ? "" : " (" + k.unit + ")", k.description);
}

bool is_stream(const std::string& input) {
  return std::filesystem::path(input).extension() == ".rays";
}

// Traces a workload spec or scene into dir/workload.rays; returns the stream's path.
std::string trace_input(const MultiOptions& o) {
  pipeline::WorkloadSpec spec = pipeline::load_workload(o.input);
  pipeline::apply_overrides(
      spec,
      pipeline::make_overrides(
          {o.resolution, o.frames, o.seed_set ? std::optional<uint64_t>(o.seed) : std::nullopt}));
  if (o.importance) spec.samples.placement = pipeline::Placement::Importance;
  if (o.orbit_set) spec.camera.orbit = o.orbit;
  if (o.warmup_set) spec.warmup_frames = o.warmup_frames;
  std::filesystem::create_directories(o.output);
  pipeline::TraceOptions options;
  options.output = o.output + "/workload.rays";
  options.generator = "rtsim " RTSIM_VERSION;
  if (!o.quiet)
    fmt::print("trace      {} ({} frames, {}x{}) into {}\n", spec.name, spec.frames, spec.width,
               spec.height, options.output);
  pipeline::trace_workload(spec, options);
  return options.output;
}

// A device-set key given with --set (hardware keys) says where it belongs.
void check_hardware_sets(const MultiOptions& o) {
  for (const std::string& assignment : o.hw_sets) {
    std::string key = assignment.substr(0, assignment.find('='));
    for (const ConfigKeyDoc& k : multi::device_set_keys())
      if (k.key == key)
        throw_input_error(
            "--set " + assignment, "",
            "a device-set key, not a hardware key: pass it as --device-set " + assignment);
  }
}

multi::DeviceSet device_set(const MultiOptions& o) {
  check_hardware_sets(o);
  multi::DeviceSet set = multi::load_device_set(o.devices_file, o.device_sets);
  if (!o.devices_file.empty() && (!o.config.empty() || !o.device_configs.empty()))
    throw InputError(
        "multi-device: give devices by --devices-file or by --config/--device-config"
        ", not both");
  if (!o.config.empty() && !o.device_configs.empty())
    throw InputError(
        "multi-device: give one config for every device (--config, with --devices) or one "
        "--device-config per device, not both");
  if (!o.device_configs.empty()) {
    if (o.devices && o.devices != o.device_configs.size())
      throw InputError(fmt::format("multi-device: --devices {} but {} --device-config", o.devices,
                                   o.device_configs.size()));
    set.devices.clear();
    for (const std::string& c : o.device_configs) set.devices.push_back({c, {}});
  } else if (o.devices_file.empty()) {
    set.devices.assign(o.devices ? o.devices : 4, multi::DeviceHardware{o.config, {}});
  } else if (o.devices) {
    throw InputError("multi-device: --devices does not apply to --devices-file");
  }
  if (!o.split.empty()) {
    set.strategies.clear();
    for (const std::string& name : o.split) {
      auto s = multi::strategy_from_name(name);
      if (!s) throw InputError("--split " + name + ": not one of static, balanced, cost, current");
      set.strategies.push_back(*s);
    }
  }
  return set;
}

int run_multi(const MultiOptions& o) {
  if (o.list_keys) {
    print_keys();
    return 0;
  }
  if (o.input.empty() || o.output.empty())
    throw InputError("multi-device: WORKLOAD_OR_STREAM and -o DIR are required (or --list-keys)");
  multi::DeviceSet set = device_set(o);
  create_output_folder(o.output);
  lock_output_folder(o.output, "rtsim multi-device");
  multi::DeviceConfigs configs(set, o.hw_sets);
  bool stream_input = is_stream(o.input);
  if (stream_input &&
      (!o.resolution.empty() || o.seed_set || o.importance || o.orbit_set || o.warmup_set))
    throw InputError(
        "multi-device: --resolution, --seed, --importance, --orbit and --warmup-frames apply to "
        "a workload, not to a stream");
  std::string stream = stream_input ? o.input : trace_input(o);
  RayStreamReader reader(stream);
  StreamHeader header = reader.header();
  Scene scene = load_stream_scene(stream, header);
  unsigned jobs = o.jobs ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
  multi::SystemCBackend backend(scene.mesh, scene.instanced, scene.instance_settings, jobs);
  multi::MultiRunOptions options;
  options.max_frames = stream_input ? o.frames : 0;
  bool tty = isatty(fileno(stderr)) != 0;
  if (!o.quiet)
    options.progress = [tty](uint32_t frame, uint32_t frames) {
      fmt::print(stderr, tty ? "\rframe {}/{}" : "frame {}/{}\n", frame + 1, frames);
    };
  auto start = std::chrono::steady_clock::now();
  multi::MultiRunResult result;
  try {
    result = multi::run_multi_device(reader, set, configs, backend, options);
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {
    fmt::print(stderr, "rtsim: multi-device: a device simulation failed: {}\n", e.what());
    return 1;
  }
  if (!o.quiet && tty) fmt::print(stderr, "\r{:<20}\r", "");
  multi::ReportInput in{stream, header, &set, &configs, &result, {}, 0};
  std::vector<uint32_t> changes = multi::change_frames(result);
  for (const multi::StrategyRun& run : result.runs)
    in.summaries.push_back(multi::summarize(run, result.devices, changes, set.settle_pct));
  in.host_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  multi::write_multi_report(o.output, in, !o.no_chart);
  reports::ChartRun chart = o.no_chart ? reports::ChartRun{true, ""}
                                       : reports::run_chart_script("multi_chart.py", {o.output});
  if (!o.quiet) {
    fmt::print("{}", multi::format_multi_summary(in));
    fmt::print("host       {:.1f} s; results in {}\n", in.host_seconds, o.output);
  }
  return reports::chart_exit_code(chart);
}

}  // namespace

void add_multi_device_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "multi-device", "Several devices render each frame together: split strategies compared");
  auto o = std::make_shared<MultiOptions>();
  cmd->add_option("input", o->input, "Ray stream (.rays), or a workload spec or scene to trace");
  cmd->add_option("-o,--output", o->output, "Folder for the report, CSV files and chart");
  cmd->add_option("--devices-file", o->devices_file, "Device set (.toml; see configs/multi/)");
  cmd->add_option("--config", o->config, "Hardware config of every device: " + kConfigForms);
  cmd->add_option("--devices", o->devices, "Number of devices with --config (default 4)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--device-config", o->device_configs,
                  "Hardware config of one device (as --config); repeat once per device")
      ->allow_extra_args(false);
  cmd->add_option("--split", o->split, "Strategies to compare: static,balanced,cost,current")
      ->delimiter(',')
      ->allow_extra_args(false);
  cmd->add_option("--set,--hw-set", o->hw_sets,
                  "Override a hardware key of every device, as in rtsim sim: --set rt.count=2")
      ->allow_extra_args(false);
  cmd->add_option("--device-set", o->device_sets,
                  "Override a device-set key: --device-set link.bandwidth_gbps=32")
      ->allow_extra_args(false);
  cmd->add_option("--frames", o->frames, "Frames: of the stream, or to trace")
      ->check(reports::frame_range());
  cmd->add_option("--resolution", o->resolution, "Image size WxH of a traced workload");
  cmd->add_option("--seed", o->seed, "Random seed of a traced workload")
      ->check(reports::non_negative())
      ->each([o](const std::string&) { o->seed_set = true; });
  cmd->add_flag("--importance", o->importance,
                "Place a traced workload's camera samples by importance (irregular samples)");
  cmd->add_option("--orbit", o->orbit, "Camera orbit of a traced workload, degrees over all frames")
      ->each([o](const std::string&) { o->orbit_set = true; });
  cmd->add_option("--warmup-frames", o->warmup_frames,
                  "Frames a traced workload's renderer runs before frame 0, writing no rays")
      ->each([o](const std::string&) { o->warmup_set = true; });
  cmd->add_option("-j,--jobs", o->jobs, "Device simulations at once (default: CPU count)");
  cmd->add_flag("--no-charts,--no-chart", o->no_chart, "Skip chart.png (no Python needed)");
  cmd->add_flag("-q,--quiet", o->quiet, "Print nothing but errors");
  cmd->add_flag("--list-keys", o->list_keys, "List every device-set key and exit");
  cmd->callback([o, &exit_code] { exit_code = run_multi(*o); });
}

}  // namespace rtsim::app
