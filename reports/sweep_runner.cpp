#include "reports/sweep_runner.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>

#include <fmt/core.h>

#include "model/sc/sim_report.h"
#include "reports/metrics.h"
#include "reports/page_util.h"
#include "reports/process_pool.h"
#include "reports/report_doc.h"
#include "reports/report_writer.h"
#include "traces/hash.h"

namespace rtsim::reports {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

Json request_of(const SweepSpec& spec, const Json& trace_request, const SweepPoint& point) {
  std::vector<std::string> sets = spec.sets;
  sets.insert(sets.end(), point.sets.begin(), point.sets.end());
  return {{"trace", trace_request},
          {"config", spec.config.empty() ? "" : fs::absolute(spec.config).string()},
          {"config_hash", spec.config.empty() ? "" : text_hash(read_file(spec.config))},
          {"sets", sets},
          {"fidelity", spec.fidelity},
          {"sample_rate", spec.sampling.rate},
          {"verify", spec.verify},
          {"rtsim", executable_fingerprint()}};
}

Json read_where(const std::string& dir) {
  try {
    Json where = Json::parse(read_file(dir + "/where.json"));
    return where.is_object() ? where : Json::object();
  } catch (const nlohmann::json::exception&) {
    return Json::object();
  }
}

std::string ran_on(const Json& where) {
  std::string engine = where.value("engine", ""), host = where.value("host", "");
  if (engine == "slurm") return fmt::format("slurm job {} on {}", where.value("job", ""), host);
  return engine.empty() ? "" : engine + " on " + host;
}

// The `rtsim run` command of a point, from its request alone.
std::vector<std::string> point_argv(const Json& request, const std::string& trace_dir,
                                    const std::string& dir) {
  std::vector<std::string> argv =
      run_child_argv(trace_dir, dir, request["fidelity"].get<std::string>(),
                     request["sample_rate"].get<uint32_t>(), request["config"].get<std::string>());
  for (const Json& s : request["sets"]) argv.insert(argv.end(), {"--set", s.get<std::string>()});
  if (!request["verify"].get<bool>()) argv.push_back("--no-verify");
  return argv;
}

std::string describe(const PointRun& p) {
  std::string out = p.workload;
  for (const auto& [key, value] : p.point->values.items()) out += " " + key + "=" + value.dump();
  return out;
}

}  // namespace

Json finished_report(const std::string& dir, const Json& request) {
  std::string old = read_file(dir + "/request.json");
  if (old.empty()) return Json();
  try {
    if (Json::parse(old) != request) return Json();
  } catch (const nlohmann::json::exception&) {
    return Json();
  }
  return whole_report(dir + "/report.json");
}

std::string host_name() {
  char name[256] = {};
  if (gethostname(name, sizeof name - 1) != 0) return "unknown";
  std::string host = name;
  return host.substr(0, host.find('.'));
}

std::vector<PointRun> plan_sweep(const SweepSpec& spec, const std::string& output) {
  std::vector<PointRun> points;
  for (const SweepWorkload& w : spec.workloads) {
    Json trace_request = trace_request_json(w.trace);
    for (const SweepPoint& point : spec.points) {
      PointRun p;
      p.request = request_of(spec, trace_request, point);
      p.id = w.name + "-" + text_hash(p.request.dump()).substr(0, 10);
      p.workload = w.name;
      p.dir = output + "/points/" + p.id;
      p.trace_dir = output + "/traces/" + w.name;
      p.point = &point;
      Json report = finished_report(p.dir, p.request);
      if (!report.is_null()) {
        p.reused = p.ok = true;
        p.metrics = flat_metrics(report);
      }
      Json where = read_where(p.dir);
      if (where["exit_code"].is_number_integer()) p.exit_code = where["exit_code"].get<int>();
      p.ran_on = ran_on(where);
      points.push_back(p);
    }
  }
  return points;
}

void trace_sweep_workloads(const SweepSpec& spec, const std::string& output, bool quiet) {
  for (const SweepWorkload& w : spec.workloads)
    trace_into(w.trace, output + "/traces/" + w.name, quiet);
}

std::vector<std::string> prepare_point(const PointRun& p) {
  fs::create_directories(p.dir);
  for (const auto& entry : fs::directory_iterator(p.dir)) fs::remove_all(entry.path());
  write_file_atomic(p.dir + "/request.json", p.request.dump(2) + "\n");
  return point_argv(p.request, p.trace_dir, p.dir);
}

void record_where(const PointRun& p, Json where) {
  where["exit_code"] = nullptr;
  write_file_atomic(p.dir + "/where.json", where.dump(2) + "\n");
}

void finish_point(PointRun& p, int exit_code) {
  p.exit_code = exit_code;
  Json where = read_where(p.dir);
  where["exit_code"] = exit_code;
  write_file_atomic(p.dir + "/where.json", where.dump(2) + "\n");
  p.ran_on = ran_on(where);
  Json report = finished_report(p.dir, p.request);
  p.ok = !report.is_null();
  if (p.ok) p.metrics = flat_metrics(report);
}

std::vector<PointRun> run_sweep(const SweepSpec& spec, const SweepRunOptions& o) {
  fs::create_directories(o.output + "/points");
  if (!o.quiet) {
    size_t configs = spec.points.size(), workloads = spec.workloads.size();
    fmt::print(
        "sweep      {}: {} config{} x {} workload{}; tracing the workloads, then finding "
        "the points done before\n",
        spec.name, configs, configs == 1 ? "" : "s", workloads, workloads == 1 ? "" : "s");
    std::fflush(stdout);
  }
  trace_sweep_workloads(spec, o.output, o.quiet);
  std::vector<PointRun> points = plan_sweep(spec, o.output);
  std::vector<ProcessJob> jobs;
  std::vector<size_t> job_point;
  for (size_t i = 0; i < points.size(); ++i)
    if (!points[i].ok) {
      jobs.push_back({prepare_point(points[i]), points[i].dir + "/run.log"});
      record_where(points[i], {{"engine", "local"}, {"host", host_name()}});
      job_point.push_back(i);
    }
  uint32_t parallel = o.jobs ? o.jobs : spec.jobs ? spec.jobs : local_cores();
  if (!o.quiet)
    fmt::print("sweep      {}: {} points, {} done before, {} to run, {} at a time\n", spec.name,
               points.size(), points.size() - jobs.size(), jobs.size(), parallel);
  auto start = std::chrono::steady_clock::now();
  size_t finished = 0;
  run_processes(jobs, parallel, [&](size_t job, int code, double) {
    PointRun& p = points[job_point[job]];
    finish_point(p, code);
    ++finished;
    if (o.quiet) return;
    double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    double eta = elapsed / double(finished) * double(jobs.size() - finished);
    std::string result = p.ok && !p.metrics["cycles"].is_null()
                             ? fmt::format("{} cycles", show(p.metrics["cycles"], Style::Integer))
                         : p.ok ? "done"
                                : fmt::format("FAILED (exit {}, see {}/run.log)", code, p.dir);
    fmt::print("[{:>3}/{}] {}: {}{}  ({:.0f} s, about {:.0f} s left)\n", finished, jobs.size(),
               describe(p), result, p.ok && code == 1 ? ", verification FAILED" : "", elapsed, eta);
    std::fflush(stdout);
  });
  return points;
}

}  // namespace rtsim::reports
