// rtsim sweep SPEC.toml -o DIR: runs every workload x hardware point of a sweep spec (a grid or
// a list over config keys), in parallel on the local cores or as a Slurm job array
// (--engine slurm), resuming an interrupted sweep without redoing finished points, and writes
// DIR/sweep.{json,csv,html,md} with curves and a Pareto chart. `--status DIR` and
// `--collect DIR` follow and merge a Slurm sweep. Exit 1 if a point failed or its verification
// found an unexplained mismatch.
#include <filesystem>
#include <memory>

#include <fmt/core.h>

#include "app/commands.h"
#include "reports/sweep_report.h"
#include "reports/sweep_slurm.h"
#include "reports/sweep_spec.h"
#include "traces/error.h"
#include "traces/output_file.h"

namespace rtsim::app {
namespace {

struct SweepOptions {
  std::string spec, output, engine = "local";
  std::string status_dir, collect_dir, slurm_task;
  uint32_t task = 0;
  uint32_t jobs = 0;
  uint64_t max_points = reports::kDefaultMaxSweepPoints;
  bool no_charts = false, quiet = false, trace_only = false;
  reports::SlurmOptions slurm;
};

// Writes the pages of the points and says how the sweep went; the exit code.
int write_results(const reports::SweepSpec& spec, const std::vector<reports::PointRun>& points,
                  const std::string& output, const SweepOptions& o) {
  nlohmann::ordered_json doc = reports::sweep_json(spec, points);
  reports::ReportOutcome out = reports::write_sweep_report(doc, output, {!o.no_charts, true});
  size_t failed = 0, unverified = 0;
  for (const reports::PointRun& p : points) {
    failed += !p.ok;
    const auto& u = p.metrics.is_object() ? p.metrics["unexplained"] : nlohmann::ordered_json();
    unverified += p.ok && !u.is_null() && u.get<uint64_t>() > 0;
  }
  if (!o.quiet) {
    for (const std::string& line : reports::objective_lines(doc))
      fmt::print("best       {}\n", line);
    fmt::print(
        "sweep      {} points: {} failed or missing, {} with unexplained mismatches; results in "
        "{}/sweep.html, sweep.csv, sweep.json\n",
        points.size(), failed, unverified, output);
  }
  int charts = reports::charts_exit_code(out, {!o.no_charts, true}, o.quiet);
  return failed + unverified > 0 ? 1 : charts;
}

std::string jobs_list(const std::vector<std::string>& jobs) {
  std::string out;
  for (size_t i = 0; i < jobs.size() && i < 5; ++i) out += (i ? ", " : "") + jobs[i];
  return jobs.size() > 5 ? out + fmt::format(" and {} more", jobs.size() - 5) : out;
}

int collect(const SweepOptions& o) {
  const std::string& dir = o.collect_dir;
  reports::SweepSpec spec = reports::read_sweep_spec(reports::slurm_sweep_spec(dir),
                                                     reports::slurm_sweep_max_points(dir));
  lock_output_folder(dir, "rtsim sweep --collect");
  reports::note_slurm_build(dir);
  std::vector<reports::PointRun> points = reports::plan_sweep(spec, dir);
  for (reports::PointRun& p : points) p.reused = false;
  std::vector<std::string> queued = reports::queued_slurm_jobs(dir);
  if (!o.quiet && !queued.empty())
    fmt::print("sweep      {} job(s) still queued or running ({}): collecting the points done\n",
               queued.size(), jobs_list(queued));
  return write_results(spec, points, dir, o);
}

// One of SPEC, --status, --collect, --slurm-task; options only where they mean something.
void check_options(const SweepOptions& o, CLI::App* cmd) {
  int modes =
      !o.spec.empty() + !o.status_dir.empty() + !o.collect_dir.empty() + !o.slurm_task.empty();
  if (modes != 1) throw InputError("sweep: give one of SPEC, --status DIR or --collect DIR");
  if (o.spec.empty())
    for (const char* name : {"--output", "--engine", "--jobs", "--trace-only", "--max-points"})
      if (cmd->count(name))
        throw InputError(std::string("sweep: ") + name + " goes with a SPEC, not --status or " +
                         "--collect");
  if (!o.spec.empty() && o.output.empty()) throw InputError("sweep: -o DIR is required");
  if (o.trace_only)
    for (const char* name : {"--jobs", "--no-charts"})
      if (cmd->count(name))
        throw InputError(std::string("sweep: ") + name + " does nothing with --trace-only");
  if (o.engine == "slurm" && (cmd->count("--jobs") || o.trace_only))
    throw InputError(std::string("sweep: ") + (o.trace_only ? "--trace-only" : "--jobs") +
                     " is an option of the local engine (--array-limit caps Slurm's tasks)");
  if (o.engine != "slurm" || o.spec.empty())
    for (const char* name : {"--partition", "--time", "--mem", "--cpus-per-task", "--array-limit",
                             "--points-per-task", "--sbatch-arg", "--dry-run"})
      if (cmd->count(name))
        throw InputError(std::string("sweep: ") + name + " is an option of --engine slurm");
}

// A Slurm sweep's files read back: a wrong type or a vanished file is bad input, not a bug.
template <typename F>
int reading_slurm_files(const std::string& what, F&& f) {
  try {
    return f();
  } catch (const nlohmann::json::exception& e) {
    throw InputError(what + ": a file of the Slurm sweep is not as rtsim wrote it: " + e.what());
  } catch (const std::filesystem::filesystem_error& e) {
    throw InputError(what + ": " + e.what());
  }
}

int run_sweep_command(const SweepOptions& o, CLI::App* cmd) {
  check_options(o, cmd);
  if (!o.status_dir.empty())
    return reading_slurm_files(o.status_dir, [&] {
      reports::print_slurm_status(o.status_dir);
      return 0;
    });
  if (!o.collect_dir.empty()) return reading_slurm_files(o.collect_dir, [&] { return collect(o); });
  if (!o.slurm_task.empty())
    return reading_slurm_files(o.slurm_task,
                               [&] { return reports::run_slurm_task(o.slurm_task, o.task); });
  reports::SweepSpec spec = reports::read_sweep_spec(o.spec, o.max_points);
  create_output_folder(o.output);
  if (o.trace_only) {  // the first job of a Slurm sweep; the submitter may still hold the lock
    reports::trace_sweep_workloads(spec, o.output, o.quiet);
    return 0;
  }
  lock_output_folder(o.output, "rtsim sweep");
  if (o.engine == "slurm")
    return reading_slurm_files(o.output, [&] {
      reports::submit_slurm_sweep(spec, o.output, o.slurm);
      return 0;
    });
  std::vector<std::string> queued = reports::queued_slurm_jobs(o.output);
  if (!queued.empty())
    throw_input_error(o.output, "",
                      "its Slurm jobs (" + jobs_list(queued) +
                          ") are still queued or running; wait for them (rtsim sweep --status " +
                          o.output + ") or scancel them before a local sweep");
  std::vector<reports::PointRun> points = reports::run_sweep(spec, {o.output, o.jobs, o.quiet});
  return write_results(spec, points, o.output, o);
}

}  // namespace

void add_sweep_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "sweep",
      "Run a grid or list of hardware points over workloads, on local cores or Slurm, resumable");
  auto o = std::make_shared<SweepOptions>();
  cmd->add_option("spec", o->spec, "Sweep spec (.toml; see reports/examples/)");
  cmd->add_option("-o,--output", o->output, "Sweep folder (results, points, traces)");
  cmd->add_option("--engine", o->engine, "Where the points run: local (default) or slurm")
      ->check(CLI::IsMember({"local", "slurm"}));
  cmd->add_option("-j,--jobs", o->jobs, "Points run at once (default: the spec's, else all cores)");
  cmd->add_option(
         "--max-points", o->max_points,
         "Refuse a sweep of more points (workloads x configs) than this, counted before a grid "
         "is expanded")
      ->check(CLI::Range(uint64_t(1), reports::kMostSweepPoints));
  cmd->add_flag("--no-charts", o->no_charts, "Write the pages without running Python");
  cmd->add_flag("-q,--quiet", o->quiet, "Print nothing but errors");
  cmd->add_flag("--trace-only", o->trace_only,
                "Trace the workloads into DIR/traces and stop (a Slurm sweep's first job)");
  cmd->add_option("--status", o->status_dir,
                  "Slurm sweep folder: points done, running, pending, failed, with job ids");
  cmd->add_option("--collect", o->collect_dir,
                  "Slurm sweep folder: merge its points into sweep.{json,csv,html,md}");
  auto* slurm = "Slurm engine";
  cmd->add_option("--partition", o->slurm.partition, "sbatch --partition")->group(slurm);
  cmd->add_option("--time", o->slurm.time_limit, "sbatch --time per job (e.g. 30, 2:00:00)")
      ->group(slurm);
  cmd->add_option("--mem", o->slurm.memory, "sbatch --mem per job (e.g. 4G)")->group(slurm);
  cmd->add_option("--cpus-per-task", o->slurm.cpus_per_task, "sbatch --cpus-per-task (1)")
      ->check(CLI::Range(1u, 4096u))
      ->group(slurm);
  cmd->add_option("--array-limit", o->slurm.array_limit,
                  "Most array tasks running at once (--array=...%N; default no limit)")
      ->check(CLI::Range(1u, 1000000u))
      ->group(slurm);
  cmd->add_option("--points-per-task", o->slurm.points_per_task,
                  "Points one array task runs in turn, for short points (1)")
      ->check(CLI::Range(1u, 1000000u))
      ->group(slurm);
  cmd->add_option("--sbatch-arg", o->slurm.sbatch_args,
                  "More sbatch options, one per use (e.g. --sbatch-arg=--account=arch)")
      ->check([](const std::string& arg) {
        return arg.rfind("-", 0) == 0 ? std::string() : "an sbatch option starts with -";
      })
      ->group(slurm);
  cmd->add_flag("--dry-run", o->slurm.dry_run, "Write and print the job scripts, submit nothing")
      ->group(slurm);
  cmd->add_option("--slurm-task", o->slurm_task, "tasks.json of a submission (run by Slurm)")
      ->group("");
  cmd->add_option("--task", o->task, "Array task index (run by Slurm)")->group("");
  cmd->callback([o, cmd, &exit_code] {
    o->slurm.quiet = o->quiet;
    exit_code = run_sweep_command(*o, cmd);
  });
}

}  // namespace rtsim::app
