// rtsim report DIR: redraws the charts and rewrites the pages of a run folder (from its
// report.json) or a sweep folder (from its sweep.json), e.g. after installing matplotlib, or
// writes the report of a `rtsim sim` folder (from its stats.json, fidelity.json and sim.json).
// Exit 1 if a chart failed.
#include <filesystem>
#include <memory>

#include <fmt/core.h>

#include "app/commands.h"
#include "reports/report_writer.h"
#include "reports/sweep_report.h"
#include "traces/error.h"

namespace rtsim::app {

void add_report_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("report", "Write the report of a run, sim or sweep folder");
  auto dir = std::make_shared<std::string>();
  auto no_charts = std::make_shared<bool>(false);
  cmd->add_option("folder", *dir,
                  "Run folder (report.json), sim folder (stats.json) or sweep folder (sweep.json)")
      ->required();
  cmd->add_flag("--no-charts", *no_charts, "Write the pages without running Python");
  cmd->callback([dir, no_charts, &exit_code] {
    reports::ReportOptions options{!*no_charts, true};
    bool sweep = std::filesystem::exists(*dir + "/sweep.json");
    reports::ReportOutcome out = sweep ? reports::rewrite_sweep_report(*dir, options)
                                       : reports::rewrite_report(*dir, options);
    exit_code = reports::charts_exit_code(out, options, false);
    fmt::print("report     {}/{}\n", *dir, sweep ? "sweep.html" : "report.html");
  });
}

}  // namespace rtsim::app
