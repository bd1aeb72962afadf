#include "reports/report_writer.h"

#include <algorithm>
#include <filesystem>

#include <fmt/core.h>

#include "model/sc/sim_report.h"
#include "reports/charts.h"
#include "reports/page_util.h"
#include "reports/report_doc.h"
#include "reports/report_pages.h"
#include "reports/sim_folder.h"
#include "traces/error.h"
#include "traces/path_name.h"

namespace rtsim::reports {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

void copy_picture(const std::string& from, const std::string& to) {
  if (from.empty() || !fs::exists(from)) return;
  write_file_atomic(to, read_file(from));
}

// Marks drawn images missing on disk as unavailable, with the reason.
void settle_images(Json& report, const std::string& run_dir, const std::string& reason) {
  for (Json& image : report["images"]) {
    if (!image["available"].get<bool>()) continue;
    if (fs::exists(run_dir + "/" + image["file"].get<std::string>())) continue;
    image["available"] = false;
    image["reason"] = image["kind"] == "picture" ? "the trace wrote no such picture" : reason;
  }
}

ReportOutcome finish(Json& report, const std::string& run_dir, const ReportOptions& options) {
  std::string json_path = run_dir + "/report.json";
  write_file_atomic(json_path, report.dump(2) + "\n");
  if (!options.pages) return {};
  ReportOutcome outcome;
  if (options.charts) {
    ChartRun charts = run_chart_script("run_charts.py", {json_path, run_dir});
    outcome = {charts.ok, charts.message};
  } else {
    outcome = {false, "charts skipped (--no-charts)"};
  }
  settle_images(report, run_dir, outcome.charts_ok ? "file missing" : outcome.message);
  write_file_atomic(json_path, report.dump(2) + "\n");
  write_file_atomic(run_dir + "/report.html", report_html(report, run_dir));
  write_file_atomic(run_dir + "/report.md", report_markdown(report));
  return outcome;
}

}  // namespace

// What the pages and charts read from a report.json written by an earlier run; everything else
// they read through at_key, which takes a missing key as null.
void require_report_fields(const Json& report, const std::string& path) {
  using K = JsonKind;
  require_fields(report, path,
                 {{"generator", K::String},
                  {"command", K::String},
                  {"workload.name", K::String},
                  {"workload.passes", K::Array},
                  {"workload.passes.*.pass", K::String},
                  {"workload.passes.*.ray_type", K::String},
                  {"workload.passes.*.rays", K::Count},
                  {"workload.passes.*.budget_per_frame", K::Count},
                  {"workload.passes.*.skipped", K::Bool},
                  {"workload.passes.*.reason", K::String},
                  {"hardware.name", K::String},
                  {"hardware.sets", K::Present},
                  {"hardware.resolved", K::Present},
                  {"fidelity.level", K::String},
                  {"dram.by_channel", K::Present},
                  {"energy", K::Present},
                  {"latency.histogram", K::Present},
                  {"hit_rates.by_type", K::Present},
                  {"time.ray_time_share", K::Present},
                  {"verification.skipped", K::Bool},
                  {"pixel_buffers", K::ObjectOrNull}});
  if (report["verification"]["skipped"].get<bool>())
    require_fields(report, path, {{"verification.reason", K::String}});
  else
    require_fields(report, path,
                   {{"verification.passed", K::Bool},
                    {"verification.rays", K::Count},
                    {"verification.agree", K::Count},
                    {"verification.mismatches", K::Count},
                    {"verification.unexplained", K::Count},
                    {"verification.by_class", K::Present}});
  if (report["pixel_buffers"].is_null()) return;
  require_fields(report, path,
                 {{"pixel_buffers.files.cycles", K::String}, {"pixel_buffers.files.*", K::String}});
  for (const auto& [key, file] : report["pixel_buffers"]["files"].items()) {
    std::string problem = path_name_problem(file.get<std::string>());
    if (!problem.empty())
      throw_input_error(path, "key pixel_buffers.files." + key, problem + " (a file of the run)");
  }
}

Json whole_report(const std::string& path) {
  std::string text = read_file(path);
  if (text.empty()) return Json();
  try {
    Json report = Json::parse(text);
    if (!report.is_object() || at_key(report, "schema") != kReportSchema) return Json();
    require_report_fields(report, path);
    return report;
  } catch (const nlohmann::json::exception&) {
    return Json();
  } catch (const InputError&) {
    return Json();
  }
}

void clear_run_folder(const std::string& run_dir, const std::string& keep) {
  std::error_code ignored;
  fs::path kept = fs::weakly_canonical(keep, ignored);
  auto holds_or_is_in_kept = [&](const fs::path& p) {
    if (keep.empty()) return false;
    fs::path own = fs::weakly_canonical(p, ignored);
    auto [o, k] = std::mismatch(own.begin(), own.end(), kept.begin(), kept.end());
    return o == own.end() || k == kept.end();
  };
  for (const char* name :
       {"report.json", "report.html", "report.md", "stats.json", "fidelity.json", "config.toml",
        "pixel_cycles.f32", "pixel_nodes.f32", "pixel_dram_bytes.f32", "images", "trace"}) {
    fs::path p = fs::path(run_dir) / name;
    std::error_code error;
    if (!fs::exists(p, error) || holds_or_is_in_kept(p)) continue;
    fs::remove_all(p, error);
    if (error)
      throw_input_error(p.string(), "",
                        "cannot remove the earlier run's output: " + error.message());
  }
}

ReportOutcome write_report(Json& report, const std::string& run_dir, const std::string& trace_dir,
                           const ReportOptions& options) {
  fs::create_directories(run_dir + "/images");
  if (!trace_dir.empty() && options.pages) {
    copy_picture(trace_dir + "/preview.png", run_dir + "/images/preview.png");
    copy_picture(trace_dir + "/preview.density-all.png", run_dir + "/images/density.png");
  }
  return finish(report, run_dir, options);
}

int charts_exit_code(const ReportOutcome& outcome, const ReportOptions& options, bool quiet) {
  if (outcome.charts_ok || !options.pages) return 0;
  if (!options.charts) {
    if (!quiet) fmt::print("charts     skipped (--no-charts)\n");
    return 0;
  }
  return chart_exit_code({false, outcome.message});
}

void clear_sim_folder_report(const std::string& sim_dir) {
  for (const char* name : {"report.json", "report.html", "report.md"}) {
    std::error_code error;
    fs::remove(fs::path(sim_dir) / name, error);
    if (error)
      throw_input_error(sim_dir + "/" + name, "",
                        "cannot remove the earlier report: " + error.message());
  }
}

ReportOutcome rewrite_report(const std::string& run_dir, const ReportOptions& options) {
  Json report = read_run_report(run_dir);
  bool pixels =
      !report["pixel_buffers"].is_null() &&
      fs::exists(run_dir + "/" + report["pixel_buffers"]["files"]["cycles"].get<std::string>());
  report["images"] = report_images(report, fs::exists(run_dir + "/images/preview.png"), pixels);
  return finish(report, run_dir, options);
}

}  // namespace rtsim::reports
