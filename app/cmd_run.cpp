// rtsim run [WORKLOAD] --config HW.toml -o DIR: the main job. Traces the workload (a spec file,
// or a built-in scene with its default spec; pica when none is given) into DIR/trace (a ray
// stream, WORKLOAD.rays or --from-trace, is taken as it is),
// simulates it at the chosen fidelity level (the full cycle-approximate model by default,
// every ray checked against Embree), and writes the report: DIR/report.html (self-contained),
// DIR/report.md, DIR/report.json, DIR/images/, next to the simulation's own results
// (stats.json, config.toml, per-pixel buffers). Exit 1 if verification finds an unexplained
// mismatch or the model stalls.
#include <memory>

#include <fmt/core.h>

#include "app/commands.h"
#include "reports/cli_options.h"
#include "reports/page_util.h"
#include "reports/report_doc.h"
#include "reports/report_writer.h"
#include "reports/run_job.h"
#include "traces/error.h"
#include "traces/output_file.h"
#include "traces/text_table.h"

namespace rtsim::app {
namespace {

struct RunOptions {
  reports::TraceRequest workload{"pica", "", 0, std::nullopt, ""};
  std::string from_trace, config, output, fidelity = "cycle", report = "full";
  std::vector<std::string> sets;
  SamplingConfig sampling;
  std::vector<std::string> sample_methods{"scale-model"};
  bool no_verify = false, no_charts = false, quiet = false;
};

std::string command_line(const RunOptions& o) {
  std::string out =
      "rtsim run " + (o.from_trace.empty() ? o.workload.workload : "--from-trace " + o.from_trace);
  if (!o.workload.resolution.empty()) out += " --resolution " + o.workload.resolution;
  if (o.workload.frames) out += " --frames " + std::to_string(o.workload.frames);
  if (o.workload.seed) out += " --seed " + std::to_string(*o.workload.seed);
  for (auto [option, value] : {std::pair{" --scene ", &o.workload.scene},
                               {" --camera ", &o.workload.camera},
                               {" --look-at ", &o.workload.look_at},
                               {" --up ", &o.workload.up}})
    if (!value->empty()) out += option + *value;
  if (!o.config.empty()) out += " --config " + o.config;
  for (const std::string& s : o.sets) out += " --set " + s;
  if (o.fidelity != "cycle") out += " --fidelity " + o.fidelity;
  if (o.fidelity == "sampled")
    out += " --sample-rate " + std::to_string(o.sampling.rate) + " --sample-method " +
           sample_method_name(o.sampling.method);
  return out + " -o " + o.output;
}

void print_summary(const nlohmann::ordered_json& r) {
  using reports::Style;
  const auto& t = r["timing"];
  fmt::print("run        {} on '{}', {} fidelity: {} rays\n",
             r["workload"]["name"].get<std::string>(), r["hardware"]["name"].get<std::string>(),
             t["level"].get<std::string>(), whole_number(t["rays"].get<uint64_t>()));
  if (!t["cycles"].is_null())
    fmt::print("timing     {} cycles{}, {:.1f} MRays/s at {} GHz\n",
               reports::show(t["cycles"], Style::Integer),
               t["cycles_ci95"].get<double>() > 0
                   ? fmt::format(" ±{}", reports::show(t["cycles_ci95"], Style::Integer))
                   : "",
               t["mrays_per_second"].get<double>(), t["clock_ghz"].get<double>());
  if (t["caveat"].is_string()) fmt::print("caveat     {}\n", t["caveat"].get<std::string>());
  if (t["bottleneck"]["text"].is_string())
    fmt::print("limit      {}\n", t["bottleneck"]["text"].get<std::string>());
  if (r["time"].contains("shader") && r["time"]["shader"].is_object())
    fmt::print("{}\n", shader_summary_line(r["time"]["shader"]));
  const auto& b = r["bandwidth"];
  std::string levels;
  if (b.contains("levels") && b["levels"].size() != 2) {  // hit rates of every level
    for (const auto& l : b["levels"])
      levels += fmt::format("{} hit rate {}  ", l["name"].get<std::string>(),
                            reports::show(l["hit_rate"], Style::Percent));
  } else {
    levels = fmt::format("L1 hit rate {}  L2 hit rate {}  ",
                         reports::show(b["l1_hit_rate"], Style::Percent),
                         reports::show(b["l2_hit_rate"], Style::Percent));
  }
  fmt::print("memory     {}DRAM {} B/ray\n", levels,
             reports::show(b["dram_bytes_per_ray"], Style::Real));
  if (r["energy"].is_object()) fmt::print("{}\n", energy_summary_line(r["energy"]));
  const auto& v = r["verification"];
  if (v["skipped"].get<bool>())
    fmt::print("verify     skipped: {}\n", v["reason"].get<std::string>());
  else
    fmt::print("verify     {} rays against Embree: {} mismatches, {} unexplained\n",
               whole_number(v["rays"].get<uint64_t>()),
               whole_number(v["mismatches"].get<uint64_t>()),
               whole_number(v["unexplained"].get<uint64_t>()));
}

int run(const RunOptions& o) {
  if (o.output.empty()) throw InputError("run: -o DIR is required");
  auto level = fidelity_level_from_name(o.fidelity);
  if (!level)
    throw InputError("run: --fidelity: unknown level '" + o.fidelity +
                     "' (functional, cache, cycle, sampled)");
  if (o.report != "full" && o.report != "json") throw InputError("run: --report: 'full' or 'json'");
  HwConfig config = load_hw_config(o.config, o.sets);
  create_output_folder(o.output);
  lock_output_folder(o.output, "rtsim run");
  reports::clear_run_folder(o.output, o.from_trace);
  reports::TraceOutcome trace = o.from_trace.empty()
                                    ? reports::trace_into(o.workload, o.output + "/trace", o.quiet)
                                    : reports::read_trace_source(o.from_trace);
  reports::RunJob job;
  job.stream = trace.stream;
  job.config = config;
  job.level = {*level, o.sampling};
  job.verify = !o.no_verify;
  job.output = o.output;
  job.progress = !o.quiet;
  reports::RunResult result = reports::run_job(job);
  if (result.stalled) {
    fmt::print(stderr, "rtsim: stall: {}", result.stall_message);
    return 1;
  }
  reports::ReportInputs inputs{&trace, &config, o.config, o.sets, &result, command_line(o)};
  nlohmann::ordered_json report = reports::build_report(inputs);
  reports::ReportOptions options{!o.no_charts, o.report == "full"};
  reports::ReportOutcome written = reports::write_report(report, o.output, trace.dir, options);
  if (!o.quiet) print_summary(report);
  int charts = reports::charts_exit_code(written, options, o.quiet);
  if (!o.quiet)
    fmt::print("report     {}/{}\n", o.output, options.pages ? "report.html" : "report.json");
  const auto& v = report["verification"];
  return !v["skipped"].get<bool>() && !v["passed"].get<bool>() ? 1 : charts;
}

}  // namespace

void add_run_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "run", "Trace, simulate, verify and report one workload on one hardware config");
  auto o = std::make_shared<RunOptions>();
  cmd->add_option("workload", o->workload.workload,
                  "Workload spec (.toml), scene file, built-in scene (default: pica) or a ray "
                  "stream (.rays: simulated as it is, like --from-trace)")
      ->capture_default_str();
  reports::add_workload_options(*cmd, o->workload);
  cmd->add_option("--from-trace", o->from_trace,
                  "Reuse a trace folder (DIR/trace of a run) or a ray stream (.rays)");
  cmd->add_option("--config", o->config, "Hardware config: " + kConfigForms);
  reports::add_config_overrides(*cmd, o->sets);
  cmd->add_option("-o,--output", o->output, "Run folder (report, results, trace)");
  cmd->add_option("--fidelity", o->fidelity, "functional, cache, cycle or sampled")
      ->capture_default_str();
  cmd->add_option("--sample-rate", o->sampling.rate, "Sampled fidelity: 1 in N rays measured")
      ->check(CLI::Range(2, 1024))
      ->capture_default_str();
  reports::add_sampling_options(*cmd, o->sampling, o->sample_methods);
  cmd->add_option("--report", o->report, "full (pages and charts) or json (report.json only)")
      ->capture_default_str();
  cmd->add_flag("--no-verify", o->no_verify, "Skip the check of every ray against Embree");
  cmd->add_flag("--no-charts", o->no_charts, "Write the pages without running Python");
  cmd->add_flag("-q,--quiet", o->quiet, "Print nothing but errors");
  cmd->callback([o, cmd, &exit_code] {
    bool stream = reports::is_stream_file(o->workload.workload);
    if (stream && !o->from_trace.empty())
      throw InputError("run: " + o->workload.workload + " and --from-trace " + o->from_trace +
                       ": give one trace");
    if (stream) o->from_trace = o->workload.workload;
    reports::refuse_workload_with_trace(*cmd, o->from_trace, stream);
    o->sampling.method = reports::sampling_methods(*cmd, o->sample_methods).front();
    exit_code = run(*o);
  });
}

}  // namespace rtsim::app
