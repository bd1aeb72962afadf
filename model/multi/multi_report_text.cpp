// The Markdown report and the printed summary of `rtsim multi-device`.
#include <algorithm>

#include <fmt/format.h>

#include "model/multi/multi_report.h"
#include "traces/text_table.h"

namespace rtsim::multi {
namespace {

std::string settle_text(const StrategySummary& s) {
  std::string text;
  for (const SettleRecord& r : s.settle)
    text += fmt::format("{}{}:{}", text.empty() ? "" : " ", r.frame,
                        r.settle_frames < 0 ? "never" : std::to_string(r.settle_frames));
  return text;
}

std::string idle_text(const StrategySummary& s) {
  std::string text;
  for (double idle : s.avg_idle_pct) text += fmt::format("{}{:.1f}", text.empty() ? "" : " ", idle);
  return text;
}

std::string hardware_text(const ReportInput& in) {
  const MultiRunResult& r = *in.result;
  if (r.runs.empty() || r.runs.front().frames.empty()) return "";
  std::string text;
  const FrameRecord& first = r.runs.front().frames.front();
  for (size_t d = 0; d < first.devices.size(); ++d)
    text += fmt::format("{}{}", d ? ", " : "", in.configs->labels()[first.devices[d].hardware]);
  return text;
}

std::string changes_text(const ReportInput& in) {
  std::string text;
  for (const DeviceChange& c : in.set->changes) {
    std::string what = c.hardware.config.empty() ? "" : c.hardware.config;
    for (const std::string& s : c.hardware.sets) what += (what.empty() ? "" : " ") + s;
    text += fmt::format("{}frame {}: device {} -> {}", text.empty() ? "" : "; ", c.frame, c.device,
                        what);
  }
  return text;
}

std::string samples_text(const DeviceSet& set) {
  return set.samples == SampleUnit::Rays ? "every ray" : "camera rays only";
}

// One row per strategy: its averages over the run.
std::string summary_table(const ReportInput& in, bool markdown) {
  std::vector<std::vector<std::string>> rows{
      {"strategy", "avg max deviation", "worst", "speed-up vs 1 device", "frame (us)",
       "1 device (us)", "copy overhead", "idle % per device", "settled (frame:frames)"}};
  for (const StrategySummary& s : in.summaries)
    rows.push_back({strategy_name(s.strategy), fmt::format("{:.2f}%", s.avg_max_dev_pct),
                    fmt::format("{:.2f}%", s.worst_max_dev_pct),
                    fmt::format("{:.2f}x", s.avg_speedup),
                    fmt::format("{:.1f}", s.avg_frame_ns / 1000),
                    fmt::format("{:.1f}", s.avg_single_ns / 1000),
                    fmt::format("{:.1f}%", s.avg_copy_overhead_pct), idle_text(s), settle_text(s)});
  std::vector<bool> numbers{false, true, true, true, true, true, true, false, false};
  return text_table(rows, markdown, numbers);
}

}  // namespace

std::string format_multi_summary(const ReportInput& in) {
  const MultiRunResult& r = *in.result;
  uint32_t frames = uint32_t(r.single_trace_ns.size());
  std::string out =
      fmt::format("devices    {} ({}); device 0 is the primary\n", r.devices, hardware_text(in));
  if (!in.set->changes.empty()) out += fmt::format("changes    {}\n", changes_text(in));
  out += fmt::format("frames     {} of {}, {}x{}, {} rays; regions along {}; samples: {}\n", frames,
                     in.header.workload, r.layout.width, r.layout.height,
                     whole_number(uint64_t(r.rays)), scan_order_name(r.layout.order),
                     samples_text(*in.set));
  out += summary_table(in, false);
  out += fmt::format(
      "max deviation: of the devices' tracing times from their mean, "
      "averaged over frames {}; settled: at or below {}%\n",
      frames > 1 ? fmt::format("1..{} (frame 0 has no measured speeds)", frames - 1)
                 : std::string("0"),
      in.set->settle_pct);
  return out;
}

std::string multi_report_markdown(const ReportInput& in, bool with_chart) {
  const MultiRunResult& r = *in.result;
  std::string md = fmt::format("# Multi-device frames: {}\n\n", in.header.workload);
  md += fmt::format(
      "Stream `{}` ({}, {}x{}), {} frames, {} rays. Device set `{}`{}: {} devices "
      "({}); device 0 is the primary. Regions run along {}. Samples counted by the balancers: {}."
      "\n\n",
      in.stream, in.header.scene_source, r.layout.width, r.layout.height, r.single_trace_ns.size(),
      r.rays, in.set->name, in.set->file.empty() ? "" : " (" + in.set->file + ")", r.devices,
      hardware_text(in), scan_order_name(r.layout.order), samples_text(*in.set));
  if (!in.set->changes.empty()) md += fmt::format("Hardware changes: {}.\n\n", changes_text(in));
  md += "## Summary\n\n" + summary_table(in, true);
  md += fmt::format(
      "\nMax deviation: max over devices of |tracing time - mean| / mean, averaged "
      "over frames after the first (frame 0 has no previous frame: static splits it by area, "
      "the balancers on the CDF of its own samples with equal speeds). Settled: frames after "
      "the start or a change until the deviation stays at or below {}%.\n\n",
      in.set->settle_pct);
  if (with_chart) md += "![per-frame figures](chart.png)\n\n";
  md += "## Per frame\n\n| frame |";
  std::string rule = "|---:|";
  for (const StrategyRun& run : r.runs) {
    md += fmt::format(" {0} max dev | {0} speed-up | {0} copy overhead (us) |",
                      strategy_name(run.strategy));
    rule += "---:|---:|---:|";
  }
  md += "\n" + rule + "\n";
  for (size_t f = 0; f < r.single_trace_ns.size(); ++f) {
    md += fmt::format("| {} |", r.runs.empty() ? f : r.runs.front().frames[f].frame);
    for (const StrategyRun& run : r.runs) {
      const FrameRecord& x = run.frames[f];
      md += fmt::format(" {:.2f}% | {:.2f}x | {:.1f} |", x.max_deviation_pct, x.speedup,
                        x.timing.copy_overhead_ns / 1000);
    }
    md += "\n";
  }
  for (const StrategyRun& run : r.runs) {
    md += fmt::format("\n## Devices, {} split: tracing / idle time (us)\n\n| frame |",
                      strategy_name(run.strategy));
    rule = "|---:|";
    for (uint32_t d = 0; d < r.devices; ++d) md += fmt::format(" device {} |", d), rule += "---:|";
    md += " frame (us) |\n" + rule + "---:|\n";
    for (const FrameRecord& x : run.frames) {
      md += fmt::format("| {} |", x.frame);
      for (const DeviceFrame& d : x.devices)
        md += fmt::format(" {:.1f} / {:.1f} |", d.timing.trace_ns / 1000, d.timing.idle_ns / 1000);
      md += fmt::format(" {:.1f} |\n", x.timing.frame_ns / 1000);
    }
  }
  return md;
}

}  // namespace rtsim::multi
