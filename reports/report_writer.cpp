#include "reports/report_writer.h"

#include <filesystem>

#include "model/sc/sim_report.h"
#include "reports/charts.h"
#include "reports/page_util.h"
#include "reports/report_doc.h"
#include "reports/report_pages.h"
#include "traces/error.h"

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

ReportOutcome write_report(Json& report, const std::string& run_dir, const std::string& trace_dir,
                           const ReportOptions& options) {
  fs::create_directories(run_dir + "/images");
  if (!trace_dir.empty() && options.pages) {
    copy_picture(trace_dir + "/preview.png", run_dir + "/images/preview.png");
    copy_picture(trace_dir + "/preview.density-all.png", run_dir + "/images/density.png");
  }
  return finish(report, run_dir, options);
}

ReportOutcome rewrite_report(const std::string& run_dir, const ReportOptions& options) {
  std::string path = run_dir + "/report.json";
  if (!fs::exists(path)) throw_input_error(run_dir, "", "no report.json (not a run folder)");
  Json report = read_json_file(path, kReportSchema);
  bool pixels =
      !report["pixel_buffers"].is_null() &&
      fs::exists(run_dir + "/" + report["pixel_buffers"]["files"]["cycles"].get<std::string>());
  report["images"] = report_images(report, fs::exists(run_dir + "/images/preview.png"), pixels);
  return finish(report, run_dir, options);
}

}  // namespace rtsim::reports
