// The Slurm engine of `rtsim sweep` (--engine slurm): the same points, ids, point runner and
// resume rules as a local sweep, run as a Slurm job array on a cluster whose nodes share the
// sweep folder. A submission writes DIR/slurm/submit-N/ (trace.sh, points.sh, tasks.json):
//   trace.sh   one job: `rtsim sweep SPEC -o DIR --trace-only` traces every workload once
//   points.sh  one array task per batch of points, after the trace job (afterok); each task
//              runs `rtsim sweep --slurm-task tasks.json --task I`, which runs its points'
//              `rtsim run` into DIR/points/ID exactly as a local sweep does
// and records the job ids in DIR/slurm/state.json, from which --status and --collect work.
// A re-submission skips the points done or still queued. Job logs: DIR/slurm/logs/. The sweep
// folder's path must not hold spaces, quotes or % (Slurm's #SBATCH lines and log patterns).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "reports/sweep_runner.h"
#include "reports/sweep_spec.h"

namespace rtsim::reports {

struct SlurmOptions {
  std::string partition;   // sbatch --partition; "" the cluster's default
  std::string time_limit;  // sbatch --time per job, Slurm's syntax (MIN, H:MM:SS, D-HH)
  std::string memory;      // sbatch --mem per job, Slurm's syntax (4G); "" the default
  uint32_t cpus_per_task = 1;
  uint32_t array_limit = 0;      // most array tasks running at once (--array=...%N); 0: no limit
  uint32_t points_per_task = 1;  // points run one after another by one array task
  std::vector<std::string> sbatch_args;  // more sbatch options, one #SBATCH line each
  bool dry_run = false;                  // write and print the scripts, submit nothing
  bool quiet = false;
};

// Submits the points of the sweep that are neither done nor queued (InputError when sbatch is
// missing or refuses a script).
void submit_slurm_sweep(const SweepSpec& spec, const std::string& output,
                        const SlurmOptions& options);

// One array task: runs the points of task `task` of a tasks.json. Returns 0 when every point
// has its report, 1 otherwise.
int run_slurm_task(const std::string& tasks_file, uint32_t task);

// `rtsim sweep --status DIR`: points done, running, pending, failed, with the job ids.
void print_slurm_status(const std::string& dir);

// The spec file a Slurm sweep folder was submitted from, and the --max-points it was read
// under (InputError if DIR is not one).
std::string slurm_sweep_spec(const std::string& dir);
uint64_t slurm_sweep_max_points(const std::string& dir);

// A line on stderr when DIR's last submission came from another build of rtsim (whose point
// ids this build does not plan).
void note_slurm_build(const std::string& dir);

// The jobs of DIR's Slurm sweep still queued or running ("12", "13_4"); empty when there are
// none, DIR is not a Slurm sweep or Slurm cannot be asked.
std::vector<std::string> queued_slurm_jobs(const std::string& dir);

}  // namespace rtsim::reports
