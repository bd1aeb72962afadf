// rtsim compare RUN... [--metric NAME]... [-o DIR]: runs side by side (run, sim or sweep
// folders), each metric with its ratio to the first run, the speed-up and each run's
// bottleneck; the table on the terminal and, with -o, DIR/compare.{json,md,html}.
#include <memory>

#include <fmt/core.h>

#include "app/commands.h"
#include "model/sc/sim_report.h"
#include "reports/compare.h"
#include "traces/output_file.h"

namespace rtsim::app {
namespace {

struct CompareOptions {
  std::vector<std::string> runs, metrics;
  std::string output;
  bool quiet = false;
};

int compare(const CompareOptions& o) {
  nlohmann::ordered_json doc = reports::compare_runs(o.runs, o.metrics);
  if (!o.quiet) fmt::print("{}", reports::compare_text(doc));
  if (o.output.empty()) return 0;
  create_output_folder(o.output);
  write_file_atomic(o.output + "/compare.json", doc.dump(2) + "\n");
  write_file_atomic(o.output + "/compare.md", reports::compare_markdown(doc));
  write_file_atomic(o.output + "/compare.html", reports::compare_html(doc));
  if (!o.quiet) fmt::print("compare    {}/compare.html, compare.md, compare.json\n", o.output);
  return 0;
}

}  // namespace

void add_compare_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "compare", "Runs side by side, with ratios to the first and each run's bottleneck");
  auto o = std::make_shared<CompareOptions>();
  cmd->add_option("runs", o->runs,
                  "Run folders (rtsim run), sim folders (rtsim sim) or sweep folders (each "
                  "finished point); the first is the one the others are compared with")
      ->required();
  cmd->add_option("--metric", o->metrics,
                  "Metrics to compare, by name as sweeps and suites name them (type.*.NAME: per "
                  "ray type); default: cycles, MRays/s, DRAM bytes, hit rates, work, area, energy")
      ->delimiter(',')
      ->allow_extra_args(false);
  cmd->add_option("-o,--output", o->output, "Folder for compare.json, compare.md, compare.html");
  cmd->add_flag("-q,--quiet", o->quiet, "Print nothing but errors");
  cmd->callback([o, &exit_code] { exit_code = compare(*o); });
}

}  // namespace rtsim::app
