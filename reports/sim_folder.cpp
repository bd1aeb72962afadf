#include "reports/sim_folder.h"

#include <filesystem>

#include "model/sc/sim_report.h"
#include "reports/page_util.h"
#include "reports/report_doc.h"
#include "reports/report_writer.h"
#include "traces/error.h"

namespace rtsim::reports {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

void write_sim_run(const std::string& dir, const SimRunRecord& record, const TraceOutcome& trace,
                   const RunResult& run) {
  Json doc = {{"schema", kSimRunSchema},   {"generator", "rtsim " RTSIM_VERSION},
              {"command", record.command}, {"config_file", record.config_file},
              {"sets", record.sets},       {"trace", trace.summary},
              {"collected", run.collected}};
  write_file_atomic(dir + "/sim.json", doc.dump(2) + "\n");
}

bool is_sim_folder(const std::string& dir) {
  return fs::exists(dir + "/stats.json");
}

namespace {

Json read_sim_part(const std::string& dir, const char* name, const char* schema) {
  std::string path = dir + "/" + name;
  if (!fs::exists(path))
    throw_input_error(path, "",
                      "missing (a sim folder needs it for a report: run this rtsim sim again)");
  return read_json_file(path, schema);
}

}  // namespace

Json sim_folder_report(const std::string& dir) {
  Json stats = read_sim_part(dir, "stats.json", kSimStatsSchema);
  Json sim = read_sim_part(dir, "sim.json", kSimRunSchema);
  Json fidelity = read_sim_part(dir, "fidelity.json", nullptr);
  using K = JsonKind;
  std::string sim_path = dir + "/sim.json";
  require_fields(sim, sim_path,
                 {{"command", K::String},
                  {"config_file", K::String},
                  {"sets", K::Array},
                  {"sets.*", K::String},
                  {"trace.workload", K::String},
                  {"trace.scene", K::String},
                  {"trace.passes", K::Array},
                  {"collected", K::ObjectOrNull}});
  require_fields(stats, dir + "/stats.json", {{"input.stream", K::String}});
  RunResult run;
  try {
    run.fidelity = FidelityResult::from_json(fidelity);
  } catch (const std::exception& e) {
    throw_input_error(dir + "/fidelity.json", "",
                      std::string("not a fidelity result: ") + e.what());
  }
  run.stats = stats;
  run.collected = sim["collected"];
  HwConfig config = load_hw_config(dir + "/config.toml");
  TraceOutcome trace{"", stats["input"]["stream"].get<std::string>(), "", sim["trace"]};
  ReportInputs inputs{&trace,
                      &config,
                      sim["config_file"].get<std::string>(),
                      sim["sets"].get<std::vector<std::string>>(),
                      &run,
                      sim["command"].get<std::string>()};
  return build_report(inputs);
}

Json read_run_report(const std::string& dir) {
  std::string path = dir + "/report.json";
  if (fs::exists(path)) {
    Json report = read_json_file(path, kReportSchema);
    require_report_fields(report, path);
    return report;
  }
  if (is_sim_folder(dir)) return sim_folder_report(dir);
  throw_input_error(dir, "",
                    "no report.json, stats.json or sweep.json (not a run, sim or sweep folder)");
}

}  // namespace rtsim::reports
