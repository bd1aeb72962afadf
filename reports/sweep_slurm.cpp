#include "reports/sweep_slurm.h"

#include <signal.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "model/sc/sim_report.h"
#include "reports/page_util.h"
#include "reports/process_pool.h"
#include "traces/error.h"
#include "traces/output_file.h"
#include "traces/path_name.h"

namespace rtsim::reports {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

constexpr const char* kStateSchema = "rtsim.sweep.slurm/1";
constexpr const char* kTasksSchema = "rtsim.sweep.slurm-tasks/1";

std::string absolute_dir(const std::string& dir) {
  std::string out = fs::absolute(dir).lexically_normal().string();
  if (out.size() > 1 && out.back() == '/') out.pop_back();
  return out;
}

std::string state_path(const std::string& dir) {
  return dir + "/slurm/state.json";
}

Json read_state(const std::string& dir) {
  if (!fs::exists(state_path(dir)))
    throw_input_error(dir, "",
                      "not a Slurm sweep folder (no slurm/state.json; `rtsim sweep SPEC -o DIR "
                      "--engine slurm` makes one)");
  return read_json_file(state_path(dir), kStateSchema);
}

std::string shell_quote(const std::string& word) {
  std::string out = "'";
  for (char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string last_line(const std::string& text) {
  std::istringstream in(text);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

std::string slurm_tool(const std::string& name) {
  std::string path = find_on_path(name);
  if (path.empty())
    throw InputError("sweep: " + name +
                     " not found on PATH: --engine slurm needs Slurm's client commands (on a "
                     "cluster's login node; here: scripts/install-deps --slurm and "
                     "scripts/slurm-local start DIR)");
  return path;
}

struct QueuedJob {
  std::string state, reason;
};
using Queue = std::map<std::string, QueuedJob>;  // by id: "12", "13_4" (one per array task)

Queue slurm_queue() {
  CommandOutput out = run_command({slurm_tool("squeue"), "--me", "-h", "-r", "-o", "%i|%T|%r"});
  if (out.exit_code != 0)
    throw InputError("sweep: squeue failed (exit " + std::to_string(out.exit_code) +
                     "): " + last_line(out.stderr_text + out.stdout_text));
  Queue jobs;
  std::istringstream in(out.stdout_text);
  for (std::string line; std::getline(in, line);) {
    size_t a = line.find('|'), b = line.find('|', a + 1);
    if (a == std::string::npos || b == std::string::npos) continue;
    jobs[line.substr(0, a)] = {line.substr(a + 1, b - a - 1), line.substr(b + 1)};
  }
  return jobs;
}

// Every submission's tasks: point id -> the job key of its latest task ("13_4").
std::map<std::string, std::string> latest_task_of_points(const std::string& dir,
                                                         const Json& state) {
  std::map<std::string, std::string> out;
  for (const Json& s : state["submissions"]) {
    Json tasks = read_json_file(dir + "/" + s["tasks"].get<std::string>(), kTasksSchema);
    for (size_t t = 0; t < tasks["tasks"].size(); ++t)
      for (const Json& point : tasks["tasks"][t])
        out[point["id"].get<std::string>()] =
            s["points_job"].get<std::string>() + "_" + std::to_string(t);
  }
  return out;
}

struct PointState {
  std::string status;  // done, running, pending, failed, not submitted
  std::string detail;
};

PointState classify(const PointRun& p, const std::map<std::string, std::string>& task_of,
                    const Queue& queue) {
  if (p.ok) return {"done", p.ran_on};
  auto task = task_of.find(p.id);
  if (task == task_of.end()) return {"not submitted", ""};
  bool started = fs::exists(p.dir + "/where.json");
  if (auto q = queue.find(task->second); q != queue.end()) {
    const QueuedJob& job = q->second;
    std::string detail = "job " + task->second + " " + job.state;
    if (job.state == "PENDING") return {"pending", detail + " (" + job.reason + ")"};
    return started ? PointState{"running", detail}
                   : PointState{"pending", detail + ", the point has not started yet"};
  }
  if (!started)
    return {"failed", "job " + task->second +
                          ": never started (cancelled, or its trace job failed: see slurm/logs)"};
  if (p.exit_code != 0)
    return {"failed",
            fmt::format("{}: exit {}, see points/{}/run.log", p.ran_on, p.exit_code, p.id)};
  return {"failed", p.ran_on + ": cancelled or killed while running"};
}

// Slurm reads these from #SBATCH lines and file name patterns: they must stay one word.
void check_slurm_word(const std::string& what, const std::string& value) {
  if (value.find_first_of(" \t\n\r%'\"\\") != std::string::npos)
    throw InputError("sweep: " + what + " '" + value +
                     "' holds a space, quote, backslash or %, which a Slurm job script cannot "
                     "carry");
}

void check_sbatch_arg(const std::string& arg) {
  if (arg.find_first_of("\n\r") != std::string::npos)
    throw InputError("sweep: --sbatch-arg holds a line break");
  static const std::set<std::string> managed = {"--array",    "--dependency",
                                                "--output",   "--error",
                                                "--chdir",    "--job-name",
                                                "--clusters", "--parsable",
                                                "--wrap",     "--kill-on-invalid-dep",
                                                "-a",         "-d",
                                                "-o",         "-e",
                                                "-D",         "-J",
                                                "-M"};
  std::string name = arg.substr(0, arg.find('='));
  if (managed.count(name) || (arg.size() > 2 && arg[1] != '-' && managed.count(arg.substr(0, 2))))
    throw InputError("sweep: --sbatch-arg " + arg +
                     ": rtsim sets that option itself (array, dependency, logs, folder, name, "
                     "cluster)");
}

std::string job_name(const std::string& name) {
  std::string out = "rtsim-";
  for (char c : name)
    out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' ? c : '_';
  return out;
}

std::string sbatch_header(const std::string& name, const std::string& dir, const std::string& log,
                          const SlurmOptions& o) {
  std::string out = "#!/bin/bash\n";
  auto line = [&](const std::string& option) { out += "#SBATCH " + option + "\n"; };
  line("--job-name=" + name);
  line("--chdir=" + dir);
  line("--output=" + log);
  line("--cpus-per-task=" + std::to_string(o.cpus_per_task));
  if (!o.partition.empty()) line("--partition=" + o.partition);
  if (!o.time_limit.empty()) line("--time=" + o.time_limit);
  if (!o.memory.empty()) line("--mem=" + o.memory);
  for (const std::string& arg : o.sbatch_args) line(arg);
  return out;
}

// What a submission does: the points it submits, and how it gets their traces.
struct Plan {
  std::vector<const PointRun*> to_run;
  size_t done = 0, queued = 0;
  bool new_trace_job = false;
  std::string trace_dependency;  // of a new trace job: "afterany:RUNNING_TRACE_JOB" or ""
  std::string points_after;      // the trace job the array waits on, if any ("" = new one)
};

Plan plan_submission(const SweepSpec& spec, const std::string& dir, const Json& state,
                     const std::vector<PointRun>& points, const Queue& queue) {
  Plan plan;
  std::map<std::string, std::string> task_of = latest_task_of_points(dir, state);
  for (const PointRun& p : points) {
    std::string status = classify(p, task_of, queue).status;
    if (status == "done")
      ++plan.done;
    else if (status == "running" || status == "pending")
      ++plan.queued;
    else
      plan.to_run.push_back(&p);
  }
  bool traces_current = true;
  for (const SweepWorkload& w : spec.workloads)
    traces_current &= trace_is_current(w.trace, dir + "/traces/" + w.name);
  if (traces_current) return plan;
  // A pending trace job reads the spec when it starts, so it covers these points too; a
  // running one may have read an older spec, so a new one follows it (never two at once).
  for (const Json& s : state["submissions"]) {
    if (!s["trace_job"].is_string()) continue;
    auto q = queue.find(s["trace_job"].get<std::string>());
    if (q == queue.end()) continue;
    if (q->second.state == "PENDING")
      plan.points_after = q->first;
    else
      plan.trace_dependency = "afterany:" + q->first;
  }
  plan.new_trace_job = plan.points_after.empty();
  return plan;
}

struct Scripts {
  std::string folder, trace, points;  // trace: "" when no new trace job is needed
  size_t tasks = 0;
};

Scripts write_scripts(const SweepSpec& spec, const std::string& dir, int number, const Plan& plan,
                      const SlurmOptions& o) {
  Scripts s;
  s.folder = dir + "/slurm/submit-" + std::to_string(number);
  fs::create_directories(s.folder);
  fs::create_directories(dir + "/slurm/logs");
  std::string rtsim = shell_quote(self_executable());
  std::string banner =
      fmt::format("# rtsim sweep {} ({}), submission {}\n", spec.name, spec.file, number);
  if (plan.new_trace_job) {
    s.trace = s.folder + "/trace.sh";
    std::string text =
        sbatch_header(job_name(spec.name + "-trace"), dir, dir + "/slurm/logs/trace-%j.log", o) +
        banner + "# Traces every workload once; the points' array job starts after it.\n" +
        fmt::format("exec {} sweep {} -o {} --trace-only --max-points {}\n", rtsim,
                    shell_quote(fs::absolute(spec.file).string()), shell_quote(dir),
                    spec.max_points);
    write_file_atomic(s.trace, text);
  }
  Json tasks = Json::array();
  for (size_t i = 0; i < plan.to_run.size(); i += o.points_per_task) {
    Json task = Json::array();
    for (size_t j = i; j < std::min(plan.to_run.size(), i + o.points_per_task); ++j)
      task.push_back({{"id", plan.to_run[j]->id}, {"workload", plan.to_run[j]->workload}});
    tasks.push_back(task);
  }
  s.tasks = tasks.size();
  std::string tasks_file = s.folder + "/tasks.json";
  write_file_atomic(
      tasks_file, Json{{"schema", kTasksSchema}, {"sweep", dir}, {"tasks", tasks}}.dump(2) + "\n");
  std::string array = "--array=0-" + std::to_string(s.tasks - 1);
  if (o.array_limit) array += "%" + std::to_string(o.array_limit);
  s.points = s.folder + "/points.sh";
  std::string text =
      sbatch_header(job_name(spec.name), dir,
                    fmt::format("{}/slurm/logs/points-{}-%A_%a.log", dir, number), o) +
      "#SBATCH " + array + "\n" + banner +
      fmt::format("# {} points in {} tasks of up to {}; each task runs its points' `rtsim run`.\n",
                  plan.to_run.size(), s.tasks, o.points_per_task) +
      fmt::format("exec {} sweep --slurm-task {} --task \"$SLURM_ARRAY_TASK_ID\"\n", rtsim,
                  shell_quote(tasks_file));
  write_file_atomic(s.points, text);
  return s;
}

std::vector<std::string> sbatch_argv(const std::string& sbatch, const std::string& dependency,
                                     const std::string& script) {
  std::vector<std::string> argv{sbatch, "--parsable"};
  if (!dependency.empty())
    argv.insert(argv.end(), {"--dependency=" + dependency, "--kill-on-invalid-dep=yes"});
  argv.push_back(script);
  return argv;
}

std::string sbatch_submit(const std::vector<std::string>& argv) {
  CommandOutput out = run_command(argv);
  std::string id = last_line(out.stdout_text);
  id = id.substr(0, id.find(';'));  // --parsable: "ID" or "ID;CLUSTER"
  if (out.exit_code != 0 || id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
    throw_input_error(argv.back(), "",
                      "sbatch refused it: " + last_line(out.stderr_text + out.stdout_text));
  return id;
}

void print_dry_run(const Scripts& scripts, const Plan& plan) {
  for (const std::string& path : {scripts.trace, scripts.points})
    if (!path.empty()) fmt::print("--- {}\n{}", path, read_file(path));
  fmt::print("--- not submitted (--dry-run); the submission would run:\n");
  if (!scripts.trace.empty())
    fmt::print("{}\n", fmt::join(sbatch_argv("sbatch", plan.trace_dependency, scripts.trace), " "));
  std::string after = plan.new_trace_job ? "TRACE_JOB_ID" : plan.points_after;
  fmt::print("{}\n", fmt::join(sbatch_argv("sbatch", after.empty() ? "" : "afterok:" + after,
                                           scripts.points),
                               " "));
}

// Blocks Ctrl-C and termination while jobs are submitted and recorded, so no job goes
// unrecorded; restores them when it goes out of scope.
class SignalsHeld {
 public:
  SignalsHeld() {
    sigset_t set;
    sigemptyset(&set);
    for (int s : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) sigaddset(&set, s);
    sigprocmask(SIG_BLOCK, &set, &old_);
  }
  ~SignalsHeld() { sigprocmask(SIG_SETMASK, &old_, nullptr); }

 private:
  sigset_t old_;
};

// Says so when the points were submitted by another build: this one plans other ids.
void note_other_build(const Json& state) {
  if (state["submissions"].empty()) return;
  std::string theirs = state["submissions"].back().value("rtsim", "");
  if (theirs != executable_fingerprint())
    fmt::print(stderr,
               "sweep: note: the last submission was made by another build of rtsim ({}; this "
               "is {}), whose points are not this build's: use that build, or resubmit\n",
               theirs, executable_fingerprint());
}

}  // namespace

std::string slurm_sweep_spec(const std::string& dir) {
  std::string spec = read_state(dir)["spec"].get<std::string>();
  if (!fs::exists(spec))
    throw_input_error(state_path(dir), "",
                      "the spec the sweep was submitted from, " + spec + ", is gone");
  return spec;
}

uint64_t slurm_sweep_max_points(const std::string& dir) {
  uint64_t max_points = read_state(dir).value("max_points", kDefaultMaxSweepPoints);
  if (max_points < 1 || max_points > kMostSweepPoints)
    throw_input_error(state_path(dir), "key max_points",
                      fmt::format("{} is not 1 to {}", max_points, kMostSweepPoints));
  return max_points;
}

void submit_slurm_sweep(const SweepSpec& spec, const std::string& output, const SlurmOptions& o) {
  std::string dir = absolute_dir(output);
  check_slurm_word("sweep folder", dir);
  for (const auto& [what, value] :
       {std::pair<const char*, const std::string&>{"--partition", o.partition},
        {"--time", o.time_limit},
        {"--mem", o.memory}})
    check_slurm_word(what, value);
  for (const std::string& arg : o.sbatch_args) check_sbatch_arg(arg);
  std::string sbatch = o.dry_run ? "sbatch" : slurm_tool("sbatch");
  std::string spec_file = fs::absolute(spec.file).lexically_normal().string();
  Json state = {{"schema", kStateSchema},
                {"spec", spec_file},
                {"max_points", spec.max_points},
                {"submissions", Json::array()}};
  if (fs::exists(state_path(dir))) {
    Json old = read_state(dir);
    if (old["spec"] != spec_file)
      throw_input_error(dir, "",
                        "holds the Slurm sweep of " + old["spec"].get<std::string>() +
                            "; give this spec another -o");
    state["submissions"] = old["submissions"];
  }
  // A dry run asks Slurm only about earlier submissions, and plans as if none were queued
  // when it cannot.
  Queue queue;
  bool ask = !o.dry_run || (!state["submissions"].empty() && !find_on_path("squeue").empty());
  try {
    if (ask) queue = slurm_queue();
  } catch (const InputError&) {
    if (!o.dry_run) throw;
  }
  std::vector<PointRun> points = plan_sweep(spec, dir);
  Plan plan = plan_submission(spec, dir, state, points, queue);
  if (!o.quiet)
    fmt::print("sweep      {}: {} points, {} done, {} queued, {} to submit\n", spec.name,
               points.size(), plan.done, plan.queued, plan.to_run.size());
  if (plan.to_run.empty()) {
    if (!o.quiet)
      fmt::print("sweep      nothing to submit: rtsim sweep --{} {}\n",
                 plan.queued ? "status" : "collect", output);
    return;
  }
  int number = int(state["submissions"].size()) + 1;
  Scripts scripts = write_scripts(spec, dir, number, plan, o);
  if (o.dry_run) return print_dry_run(scripts, plan);

  SignalsHeld held;
  for (const PointRun* p : plan.to_run) prepare_point(*p);
  std::string trace_job = plan.points_after;
  if (plan.new_trace_job)
    trace_job = sbatch_submit(sbatch_argv(sbatch, plan.trace_dependency, scripts.trace));
  std::string points_job;
  try {
    points_job = sbatch_submit(
        sbatch_argv(sbatch, trace_job.empty() ? "" : "afterok:" + trace_job, scripts.points));
  } catch (const InputError&) {
    if (plan.new_trace_job) run_command({slurm_tool("scancel"), trace_job});
    throw;
  }
  state["submissions"].push_back(
      {{"number", number},
       {"trace_job", plan.new_trace_job ? Json(trace_job) : Json()},
       {"points_job", points_job},
       {"tasks", fs::relative(scripts.folder + "/tasks.json", dir).string()},
       {"rtsim", executable_fingerprint()}});
  write_file_atomic(state_path(dir), state.dump(2) + "\n");
  if (!o.quiet)
    fmt::print(
        "sweep      submitted {} point{} as array job {} ({} task{}{}); logs in {}/slurm/logs\n"
        "           rtsim sweep --status {}   then   rtsim sweep --collect {}\n",
        plan.to_run.size(), plan.to_run.size() == 1 ? "" : "s", points_job, scripts.tasks,
        scripts.tasks == 1 ? "" : "s", trace_job.empty() ? "" : ", after trace job " + trace_job,
        dir, output, output);
}

namespace {

// A tasks file's shape; a point's id and workload name its folders (whose contents a task
// clears), so each must be one path component.
void check_tasks(const Json& tasks, const std::string& file) {
  require_fields(tasks, file,
                 {{"sweep", JsonKind::String},
                  {"tasks", JsonKind::Array},
                  {"tasks.*", JsonKind::Array},
                  {"tasks.*.*.id", JsonKind::String},
                  {"tasks.*.*.workload", JsonKind::String}});
  for (size_t t = 0; t < tasks["tasks"].size(); ++t)
    for (size_t i = 0; i < tasks["tasks"][t].size(); ++i)
      for (const char* key : {"id", "workload"}) {
        std::string problem = path_name_problem(tasks["tasks"][t][i][key].get<std::string>());
        if (!problem.empty())
          throw_input_error(file, fmt::format("key tasks.{}.{}.{}", t, i, key), problem);
      }
}

}  // namespace

int run_slurm_task(const std::string& tasks_file, uint32_t task) {
  Json tasks = read_json_file(tasks_file, kTasksSchema);
  check_tasks(tasks, tasks_file);
  if (task >= tasks["tasks"].size())
    throw_input_error(
        tasks_file, "",
        fmt::format("has {} tasks; there is no task {}", tasks["tasks"].size(), task));
  std::string dir = tasks["sweep"].get<std::string>();
  const char* array_job = std::getenv("SLURM_ARRAY_JOB_ID");
  const char* job = std::getenv("SLURM_JOB_ID");
  std::string job_key = array_job ? std::string(array_job) + "_" + std::to_string(task)
                        : job     ? std::string(job)
                                  : "none";
  Json where = {{"engine", "slurm"}, {"host", host_name()}, {"job", job_key}};
  int failed = 0;
  for (const Json& entry : tasks["tasks"][task]) {
    PointRun p;
    p.id = entry["id"].get<std::string>();
    p.workload = entry["workload"].get<std::string>();
    p.dir = dir + "/points/" + p.id;
    p.trace_dir = dir + "/traces/" + p.workload;
    try {  // a point that cannot run fails alone; the task goes on with the next
      p.request = read_json_file(p.dir + "/request.json", nullptr);
      if (!finished_report(p.dir, p.request).is_null()) {
        fmt::print("point {}: done before\n", p.id);
        continue;
      }
      if (p.request["rtsim"] != executable_fingerprint()) {
        std::string why = fmt::format(
            "point {}: the rtsim on {} ({}, build {}) is not the build that planned the sweep "
            "({}); run the same build on every node\n",
            p.id, host_name(), self_executable(), executable_fingerprint(),
            p.request["rtsim"].get<std::string>());
        fmt::print(stderr, "{}", why);
        write_file_atomic(p.dir + "/run.log", why);
        record_where(p, where);
        finish_point(p, 2);
        ++failed;
        continue;
      }
      std::vector<std::string> argv = prepare_point(p);
      record_where(p, where);
      fmt::print("point {}: running on {} as job {}\n", p.id, host_name(), job_key);
      std::fflush(stdout);
      run_processes({{argv, p.dir + "/run.log"}}, 1, [&](size_t, int code, double seconds) {
        finish_point(p, code);
        fmt::print("point {}: {} (exit {}, {:.1f} s)\n", p.id,
                   p.ok ? "done" : "FAILED, see " + p.dir + "/run.log", code, seconds);
      });
      failed += !p.ok;
    } catch (const std::exception& e) {
      fmt::print(stderr, "point {}: cannot run: {}\n", p.id, e.what());
      ++failed;
    }
  }
  return failed ? 1 : 0;
}

void print_slurm_status(const std::string& dir_in) {
  std::string dir = absolute_dir(dir_in);
  Json state = read_state(dir);
  note_other_build(state);
  SweepSpec spec = read_sweep_spec(slurm_sweep_spec(dir), slurm_sweep_max_points(dir));
  Queue queue = slurm_queue();
  std::map<std::string, std::string> task_of = latest_task_of_points(dir, state);
  std::map<std::string, size_t> counts;
  std::string lines;
  for (const PointRun& p : plan_sweep(spec, dir)) {
    PointState s = classify(p, task_of, queue);
    ++counts[s.status];
    lines += fmt::format("  {:<22} {:<13} {}\n", p.id, s.status, s.detail);
  }
  fmt::print(
      "sweep      {} ({}): {} points: {} done, {} running, {} pending, {} failed, {} not "
      "submitted\n",
      spec.name, spec.file, spec.points.size() * spec.workloads.size(), counts["done"],
      counts["running"], counts["pending"], counts["failed"], counts["not submitted"]);
  for (const Json& s : state["submissions"]) {
    std::string trace = "no trace job";
    if (s["trace_job"].is_string()) {
      std::string id = s["trace_job"].get<std::string>();
      auto q = queue.find(id);
      trace = "trace job " + id + " " + (q != queue.end() ? q->second.state : "ended");
    }
    fmt::print("submission {}: {}, array job {}\n", s["number"].get<int>(), trace,
               s["points_job"].get<std::string>());
  }
  fmt::print("{}", lines);
  if (counts["failed"] + counts["not submitted"] > 0)
    fmt::print("resubmit the failed and missing points: rtsim sweep {} -o {} --engine slurm\n",
               spec.file, dir_in);
  else if (counts["running"] + counts["pending"] == 0)
    fmt::print("every point is done: rtsim sweep --collect {}\n", dir_in);
}

void note_slurm_build(const std::string& dir) {
  note_other_build(read_state(dir));
}

std::vector<std::string> queued_slurm_jobs(const std::string& dir) {
  if (!fs::exists(state_path(dir)) || find_on_path("squeue").empty()) return {};
  std::vector<std::string> out;
  try {
    Json state = read_state(dir);
    Queue queue = slurm_queue();
    for (const Json& s : state["submissions"]) {
      std::vector<std::string> ids{s["points_job"].get<std::string>()};
      if (s["trace_job"].is_string()) ids.push_back(s["trace_job"].get<std::string>());
      for (const auto& [id, job] : queue)
        for (const std::string& mine : ids)
          if (id == mine || id.rfind(mine + "_", 0) == 0) out.push_back(id);
    }
  } catch (const InputError&) {
    return {};  // Slurm cannot be asked: nothing of ours can be seen running
  }
  return out;
}

}  // namespace rtsim::reports
