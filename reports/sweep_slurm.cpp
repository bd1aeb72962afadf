#include "reports/sweep_slurm.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>

#include <fmt/core.h>

#include "model/sc/sim_report.h"
#include "reports/page_util.h"
#include "reports/process_pool.h"
#include "traces/error.h"
#include "traces/output_file.h"

namespace rtsim::reports {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

constexpr const char* kStateSchema = "rtsim.sweep.slurm/1";
constexpr const char* kTasksSchema = "rtsim.sweep.slurm-tasks/1";

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

// This user's jobs in the queue by id ("12", "13_4": one line per array task).
std::map<std::string, QueuedJob> slurm_queue() {
  CommandOutput out = run_command({slurm_tool("squeue"), "--me", "-h", "-r", "-o", "%i|%T|%r"});
  if (out.exit_code != 0)
    throw InputError("sweep: squeue failed (exit " + std::to_string(out.exit_code) +
                     "): " + last_line(out.stderr_text + out.stdout_text));
  std::map<std::string, QueuedJob> jobs;
  std::istringstream in(out.stdout_text);
  for (std::string line; std::getline(in, line);) {
    size_t a = line.find('|'), b = line.find('|', a + 1);
    if (a == std::string::npos || b == std::string::npos) continue;
    jobs[line.substr(0, a)] = {line.substr(a + 1, b - a - 1), line.substr(b + 1)};
  }
  return jobs;
}

// Every submission's task list: point id -> its latest job key ("13_4").
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

std::string sbatch_submit(const std::vector<std::string>& argv, const std::string& script) {
  CommandOutput out = run_command(argv);
  std::string id = last_line(out.stdout_text);
  id = id.substr(0, id.find(';'));  // --parsable: "ID" or "ID;CLUSTER"
  if (out.exit_code != 0 || id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
    throw_input_error(script, "",
                      "sbatch refused it: " + last_line(out.stderr_text + out.stdout_text));
  return id;
}

std::string sbatch_header(const std::string& job_name, const std::string& dir,
                          const std::string& log, const SlurmOptions& o) {
  std::string out = "#!/bin/bash\n";
  auto line = [&](const std::string& option) { out += "#SBATCH " + option + "\n"; };
  line("--job-name=" + job_name);
  line("--chdir=" + dir);
  line("--output=" + log);
  line("--cpus-per-task=" + std::to_string(o.cpus_per_task));
  if (!o.partition.empty()) line("--partition=" + o.partition);
  if (!o.time_limit.empty()) line("--time=" + o.time_limit);
  if (!o.memory.empty()) line("--mem=" + o.memory);
  for (const std::string& arg : o.sbatch_args) line(arg);
  return out;
}

struct Scripts {
  std::string folder, trace, points;  // trace: "" when no trace job is needed
  size_t tasks = 0;
};

Scripts write_scripts(const SweepSpec& spec, const std::string& dir, int number,
                      const std::vector<const PointRun*>& to_run, bool trace_needed,
                      const SlurmOptions& o) {
  Scripts s;
  s.folder = dir + "/slurm/submit-" + std::to_string(number);
  fs::create_directories(s.folder);
  fs::create_directories(dir + "/slurm/logs");
  std::string rtsim = shell_quote(self_executable());
  std::string banner =
      fmt::format("# rtsim sweep {} ({}), submission {}\n", spec.name, spec.file, number);
  if (trace_needed) {
    s.trace = s.folder + "/trace.sh";
    std::string text =
        sbatch_header("rtsim-" + spec.name + "-trace", dir, dir + "/slurm/logs/trace-%j.log", o) +
        banner + "# Traces every workload once; the points' array job starts after it.\n" +
        fmt::format("exec {} sweep {} -o {} --trace-only\n", rtsim,
                    shell_quote(fs::absolute(spec.file).string()), shell_quote(dir));
    write_file_atomic(s.trace, text);
  }
  Json tasks = Json::array();
  for (size_t i = 0; i < to_run.size(); i += o.points_per_task) {
    Json task = Json::array();
    for (size_t j = i; j < std::min(to_run.size(), i + o.points_per_task); ++j)
      task.push_back({{"id", to_run[j]->id}, {"workload", to_run[j]->workload}});
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
      sbatch_header("rtsim-" + spec.name, dir,
                    fmt::format("{}/slurm/logs/points-{}-%A_%a.log", dir, number), o) +
      "#SBATCH " + array + "\n" + banner +
      fmt::format("# {} points in {} tasks of up to {}; each task runs its points' `rtsim run`.\n",
                  to_run.size(), s.tasks, o.points_per_task) +
      fmt::format("exec {} sweep --slurm-task {} --task \"$SLURM_ARRAY_TASK_ID\"\n", rtsim,
                  shell_quote(tasks_file));
  write_file_atomic(s.points, text);
  return s;
}

std::vector<std::string> points_sbatch_argv(const std::string& sbatch, const std::string& after,
                                            const std::string& script) {
  std::vector<std::string> argv{sbatch, "--parsable"};
  if (!after.empty())
    argv.insert(argv.end(), {"--dependency=afterok:" + after, "--kill-on-invalid-dep=yes"});
  argv.push_back(script);
  return argv;
}

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : " ") + w;
  return out;
}

}  // namespace

std::string slurm_sweep_spec(const std::string& dir) {
  std::string spec = read_state(dir)["spec"].get<std::string>();
  if (!fs::exists(spec))
    throw_input_error(state_path(dir), "",
                      "the spec the sweep was submitted from, " + spec + ", is gone");
  return spec;
}

void submit_slurm_sweep(const SweepSpec& spec, const std::string& output, const SlurmOptions& o) {
  std::string dir = fs::absolute(output).lexically_normal().string();
  if (dir.size() > 1 && dir.back() == '/') dir.pop_back();
  std::string sbatch = o.dry_run ? "sbatch" : slurm_tool("sbatch");
  std::string spec_file = fs::absolute(spec.file).lexically_normal().string();
  Json state = {{"schema", kStateSchema}, {"spec", spec_file}, {"submissions", Json::array()}};
  if (fs::exists(state_path(dir))) {
    state = read_state(dir);
    if (state["spec"] != spec_file)
      throw_input_error(dir, "",
                        "holds the Slurm sweep of " + state["spec"].get<std::string>() +
                            "; give this spec another -o");
  }
  std::map<std::string, QueuedJob> queue =
      o.dry_run ? std::map<std::string, QueuedJob>() : slurm_queue();
  std::map<std::string, std::string> task_of = latest_task_of_points(dir, state);
  std::vector<PointRun> points = plan_sweep(spec, dir);
  std::vector<const PointRun*> to_run;
  size_t done = 0, queued = 0;
  for (const PointRun& p : points) {
    auto task = task_of.find(p.id);
    if (p.ok)
      ++done;
    else if (task != task_of.end() && queue.count(task->second))
      ++queued;
    else
      to_run.push_back(&p);
  }
  if (!o.quiet)
    fmt::print("sweep      {}: {} points, {} done, {} queued, {} to submit\n", spec.name,
               points.size(), done, queued, to_run.size());
  if (to_run.empty()) {
    if (!o.quiet)
      fmt::print("sweep      nothing to submit: rtsim sweep --{} {}\n",
                 queued ? "status" : "collect", output);
    return;
  }
  bool trace_needed = false;
  for (const SweepWorkload& w : spec.workloads)
    trace_needed |= !trace_is_current(w.trace, dir + "/traces/" + w.name);
  std::string after;  // a trace job of an earlier submission still queued covers this one too
  for (const Json& s : state["submissions"])
    if (s["trace_job"].is_string() && queue.count(s["trace_job"].get<std::string>()))
      after = s["trace_job"].get<std::string>();
  int number = int(state["submissions"].size()) + 1;
  Scripts scripts = write_scripts(spec, dir, number, to_run, trace_needed && after.empty(), o);
  if (o.dry_run) {
    for (const std::string& path : {scripts.trace, scripts.points})
      if (!path.empty()) fmt::print("--- {}\n{}", path, read_file(path));
    fmt::print("--- not submitted (--dry-run); the submission would run:\n");
    if (!scripts.trace.empty()) fmt::print("{} --parsable {}\n", sbatch, scripts.trace);
    bool waits = !scripts.trace.empty() || !after.empty();
    fmt::print("{}\n",
               joined(points_sbatch_argv(sbatch, after.empty() && waits ? "TRACE_JOB_ID" : after,
                                         scripts.points)));
    if (!waits) fmt::print("(the traces are current: the array needs no trace job)\n");
    return;
  }
  for (const PointRun* p : to_run) prepare_point(*p, Json());
  Json submission = {{"number", number},
                     {"trace_job", nullptr},
                     {"points_job", ""},
                     {"tasks", fs::relative(scripts.folder + "/tasks.json", dir).string()}};
  if (!scripts.trace.empty()) {
    after = sbatch_submit({sbatch, "--parsable", scripts.trace}, scripts.trace);
    submission["trace_job"] = after;
  }
  std::string points_job;
  try {
    points_job = sbatch_submit(points_sbatch_argv(sbatch, after, scripts.points), scripts.points);
  } catch (const InputError&) {
    if (submission["trace_job"].is_string())
      run_command({find_on_path("scancel"), submission["trace_job"].get<std::string>()});
    throw;
  }
  submission["points_job"] = points_job;
  state["submissions"].push_back(submission);
  write_file_atomic(state_path(dir), state.dump(2) + "\n");
  if (!o.quiet)
    fmt::print(
        "sweep      submitted {} point{} as array job {} ({} task{}{}); logs in {}/slurm/logs\n"
        "           rtsim sweep --status {}   then   rtsim sweep --collect {}\n",
        to_run.size(), to_run.size() == 1 ? "" : "s", points_job, scripts.tasks,
        scripts.tasks == 1 ? "" : "s", after.empty() ? "" : ", after trace job " + after, dir,
        output, output);
}

int run_slurm_task(const std::string& tasks_file, uint32_t task) {
  Json tasks = read_json_file(tasks_file, kTasksSchema);
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
    p.request = read_json_file(p.dir + "/request.json", nullptr);
    if (!finished_report(p.dir, p.request).is_null()) {
      fmt::print("point {}: done before\n", p.id);
      continue;
    }
    std::vector<std::string> argv = prepare_point(p, where);
    if (p.request["rtsim"] != executable_fingerprint()) {
      std::string why = fmt::format(
          "point {}: the rtsim on {} ({}, build {}) is not the build that planned the sweep "
          "({}); run the same build on every node\n",
          p.id, host_name(), self_executable(), executable_fingerprint(),
          p.request["rtsim"].get<std::string>());
      fmt::print(stderr, "{}", why);
      write_file_atomic(p.dir + "/run.log", why);
      finish_point(p, 2);
      ++failed;
      continue;
    }
    fmt::print("point {}: running on {} as job {}\n", p.id, host_name(), job_key);
    std::fflush(stdout);
    run_processes({{argv, p.dir + "/run.log"}}, 1, [&](size_t, int code, double seconds) {
      finish_point(p, code);
      fmt::print("point {}: {} (exit {}, {:.1f} s)\n", p.id,
                 p.ok ? "done" : "FAILED, see " + p.dir + "/run.log", code, seconds);
    });
    failed += !p.ok;
  }
  return failed ? 1 : 0;
}

void print_slurm_status(const std::string& dir) {
  Json state = read_state(dir);
  SweepSpec spec = read_sweep_spec(slurm_sweep_spec(dir));
  std::map<std::string, QueuedJob> queue = slurm_queue();
  std::map<std::string, std::string> task_of = latest_task_of_points(dir, state);
  std::vector<PointRun> points = plan_sweep(spec, fs::absolute(dir).lexically_normal().string());
  std::map<std::string, size_t> counts;
  std::string lines;
  for (const PointRun& p : points) {
    auto task = task_of.find(p.id);
    std::string status, detail;
    if (p.ok) {
      status = "done";
      detail = p.ran_on;
    } else if (task == task_of.end()) {
      status = "not submitted";
    } else if (auto q = queue.find(task->second); q != queue.end()) {
      bool started = q->second.state != "PENDING" && fs::exists(p.dir + "/where.json");
      status = started ? "running" : "pending";
      detail =
          "job " + task->second + " " + q->second.state +
          (q->second.reason.empty() || q->second.reason == "None" ? ""
                                                                  : " (" + q->second.reason + ")") +
          (q->second.state != "PENDING" && !started ? ", the point waits its turn" : "");
    } else {
      status = "failed";
      std::string where = fs::exists(p.dir + "/where.json") ? p.ran_on : "job " + task->second;
      detail =
          where + ": " +
          (!fs::exists(p.dir + "/where.json")
               ? "never started (cancelled, or its trace job failed: see slurm/logs)"
           : p.exit_code != 0 ? fmt::format("exit {}, see points/{}/run.log", p.exit_code, p.id)
                              : "cancelled or killed while running");
    }
    ++counts[status];
    lines += fmt::format("  {:<22} {:<13} {}\n", p.id, status, detail);
  }
  fmt::print(
      "sweep      {} ({}): {} points: {} done, {} running, {} pending, {} failed, {} not "
      "submitted\n",
      spec.name, spec.file, points.size(), counts["done"], counts["running"], counts["pending"],
      counts["failed"], counts["not submitted"]);
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
               spec.file, dir);
  else if (counts["running"] + counts["pending"] == 0)
    fmt::print("every point is done: rtsim sweep --collect {}\n", dir);
}

std::vector<std::string> queued_slurm_jobs(const std::string& dir) {
  if (!fs::exists(state_path(dir)) || find_on_path("squeue").empty()) return {};
  std::vector<std::string> out;
  try {
    Json state = read_state(dir);
    std::map<std::string, QueuedJob> queue = slurm_queue();
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
