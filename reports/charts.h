// Charts and heatmaps are drawn by the matplotlib scripts in reports/charts/, run with
// /usr/bin/python3 (Debian's python3-matplotlib; the `python3` first on PATH may lack it).
// The scripts use the Agg backend and write PNGs without a Software tag or timestamps, so the
// same data gives the same bytes. RTSIM_PYTHON and RTSIM_CHARTS_DIR override the interpreter
// and the scripts' folder.
#pragma once

#include <string>
#include <vector>

namespace rtsim::reports {

struct ChartRun {
  bool ok = false;
  std::string message;  // why not (the script's last error line, or a missing interpreter)
};

std::string charts_dir();

// Runs one script of charts_dir() with args; waits for it.
ChartRun run_chart_script(const std::string& script, const std::vector<std::string>& args);

// A command's exit code for the charts it asked for: 0 if drawn; else 1, after one stderr line
// with the reason, `rtsim: charts failed: WHY` (the command's other outputs are written).
int chart_exit_code(const ChartRun& run);

}  // namespace rtsim::reports
