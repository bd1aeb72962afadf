// A `rtsim sim` folder read as a run, so that `rtsim report` and `rtsim compare` take it like a
// run folder. Beside stats.json, config.toml and the pixel buffers, `rtsim sim` writes (through
// reports::run_job, as `rtsim run` does) fidelity.json, and sim.json: what the report needs that
// the stats do not hold (schema rtsim.sim.run/1: the command line, --config and --set, the
// stream's summary, the latency histogram and retirement timeline of reports::RunCollector).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "reports/run_job.h"
#include "reports/trace_step.h"

namespace rtsim::reports {

constexpr const char* kSimRunSchema = "rtsim.sim.run/1";

struct SimRunRecord {
  std::string command, config_file;
  std::vector<std::string> sets;
};

// Writes dir/sim.json (through a temporary name).
void write_sim_run(const std::string& dir, const SimRunRecord& record, const TraceOutcome& trace,
                   const RunResult& run);

// Whether dir holds a `rtsim sim` result (stats.json).
bool is_sim_folder(const std::string& dir);

// The report of a sim folder (report_doc.h), as `rtsim run` builds it from the same results.
// InputError naming the file and key for a file that is missing, not valid JSON or lacks a
// key the report reads (a folder of an older rtsim sim, without sim.json, says to rerun it).
nlohmann::ordered_json sim_folder_report(const std::string& dir);

// The report of a run folder (its report.json) or of a sim folder (built as above), in memory.
// InputError if dir is neither.
nlohmann::ordered_json read_run_report(const std::string& dir);

}  // namespace rtsim::reports
