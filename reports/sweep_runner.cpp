#include "reports/sweep_runner.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include <fmt/core.h>

#include "model/sc/sim_report.h"
#include "reports/metrics.h"
#include "reports/page_util.h"
#include "reports/process_pool.h"
#include "reports/report_doc.h"
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

// The report of a finished point, or null.
Json finished_report(const std::string& dir, const Json& request) {
  std::string old = read_file(dir + "/request.json");
  std::string report = read_file(dir + "/report.json");
  if (old.empty() || report.empty()) return Json();
  try {
    if (Json::parse(old) != request) return Json();
    Json r = Json::parse(report);
    return r.value("schema", "") == kReportSchema ? r : Json();
  } catch (const nlohmann::json::exception&) {
    return Json();
  }
}

std::vector<std::string> run_argv(const SweepSpec& spec, const std::string& trace_dir,
                                  const Json& request, const std::string& dir) {
  std::vector<std::string> argv =
      run_child_argv(trace_dir, dir, spec.fidelity, spec.sampling.rate, spec.config);
  for (const Json& s : request["sets"]) argv.insert(argv.end(), {"--set", s.get<std::string>()});
  if (!spec.verify) argv.push_back("--no-verify");
  return argv;
}

std::string describe(const PointRun& p) {
  std::string out = p.workload;
  for (const auto& [key, value] : p.point->values.items()) out += " " + key + "=" + value.dump();
  return out;
}

}  // namespace

std::vector<PointRun> run_sweep(const SweepSpec& spec, const SweepRunOptions& o) {
  fs::create_directories(o.output + "/points");
  std::vector<PointRun> points;
  std::vector<ProcessJob> jobs;
  std::vector<size_t> job_point;
  if (!o.quiet) {
    size_t configs = spec.points.size(), workloads = spec.workloads.size();
    fmt::print(
        "sweep      {}: {} config{} x {} workload{}; tracing the workloads, then finding "
        "the points done before\n",
        spec.name, configs, configs == 1 ? "" : "s", workloads, workloads == 1 ? "" : "s");
    std::fflush(stdout);
  }
  for (const SweepWorkload& w : spec.workloads) {
    std::string trace_dir = o.output + "/traces/" + w.name;
    TraceOutcome trace = trace_into(w.trace, trace_dir, o.quiet);
    for (const SweepPoint& point : spec.points) {
      Json request = request_of(spec, trace.summary["request"], point);
      PointRun p;
      p.id = w.name + "-" + text_hash(request.dump()).substr(0, 10);
      p.workload = w.name;
      p.dir = o.output + "/points/" + p.id;
      p.point = &point;
      Json report = finished_report(p.dir, request);
      if (!report.is_null()) {
        p.reused = p.ok = true;
        p.metrics = flat_metrics(report);
      } else {
        fs::create_directories(p.dir);
        write_file_atomic(p.dir + "/request.json", request.dump(2) + "\n");
        jobs.push_back({run_argv(spec, trace_dir, request, p.dir), p.dir + "/run.log"});
        job_point.push_back(points.size());
      }
      points.push_back(p);
    }
  }
  uint32_t parallel = o.jobs ? o.jobs : spec.jobs ? spec.jobs : local_cores();
  if (!o.quiet)
    fmt::print("sweep      {}: {} points, {} done before, {} to run, {} at a time\n", spec.name,
               points.size(), points.size() - jobs.size(), jobs.size(), parallel);
  auto start = std::chrono::steady_clock::now();
  size_t finished = 0;
  run_processes(jobs, parallel, [&](size_t job, int code, double) {
    PointRun& p = points[job_point[job]];
    p.exit_code = code;
    Json report = finished_report(p.dir, Json::parse(read_file(p.dir + "/request.json")));
    p.ok = !report.is_null();
    if (p.ok) p.metrics = flat_metrics(report);
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
