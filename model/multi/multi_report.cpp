#include "model/multi/multi_report.h"

#include <filesystem>

#include <fmt/format.h>

#include "model/sc/sim_report.h"

namespace rtsim::multi {
namespace {

nlohmann::ordered_json summary_json(const StrategySummary& s) {
  nlohmann::ordered_json settle = nlohmann::ordered_json::array();
  for (const SettleRecord& r : s.settle)
    settle.push_back({{"frame", r.frame}, {"settle_frames", r.settle_frames}});
  return {{"strategy", strategy_name(s.strategy)},
          {"frames", s.frames},
          {"avg_max_deviation_pct", s.avg_max_dev_pct},
          {"avg_max_deviation_all_frames_pct", s.avg_max_dev_all_pct},
          {"worst_max_deviation_pct", s.worst_max_dev_pct},
          {"avg_speedup", s.avg_speedup},
          {"avg_frame_ns", s.avg_frame_ns},
          {"avg_single_device_frame_ns", s.avg_single_ns},
          {"avg_copy_overhead_pct", s.avg_copy_overhead_pct},
          {"avg_copy_bytes", s.avg_copy_bytes},
          {"avg_idle_pct", s.avg_idle_pct},
          {"settle", settle}};
}

nlohmann::ordered_json frame_json(const FrameRecord& r) {
  nlohmann::ordered_json devices = nlohmann::ordered_json::array();
  for (const DeviceFrame& d : r.devices) {
    const DeviceTiming& t = d.timing;
    devices.push_back({{"hardware", d.hardware},
                       {"region", {d.region.begin, d.region.end}},
                       {"pixels", d.pixels},
                       {"samples", d.samples},
                       {"rays", d.rays},
                       {"cycles", d.cycles},
                       {"cost", d.cost},
                       {"start_ns", t.start_ns},
                       {"trace_ns", t.trace_ns},
                       {"end_ns", t.end_ns},
                       {"copy_in_ns", t.copy_in_ns},
                       {"copy_out_ns", t.copy_out_ns},
                       {"bytes_in", t.bytes_in},
                       {"bytes_out", t.bytes_out},
                       {"busy_ns", t.busy_ns},
                       {"idle_ns", t.idle_ns}});
  }
  const FrameTiming& t = r.timing;
  return {{"frame", r.frame},
          {"frame_ns", t.frame_ns},
          {"single_device_frame_ns", r.single_ns},
          {"speedup", r.speedup},
          {"max_deviation_pct", r.max_deviation_pct},
          {"raygen_ns", t.raygen_ns},
          {"filter_ns", t.filter_ns},
          {"copy_ns", t.copy_ns},
          {"copy_bytes", t.copy_bytes},
          {"copy_overhead_ns", t.copy_overhead_ns},
          {"devices", devices}};
}

}  // namespace

nlohmann::ordered_json multi_report_json(const ReportInput& in) {
  const MultiRunResult& result = *in.result;
  nlohmann::ordered_json j;
  j["schema"] = kMultiReportSchema;
  j["input"] = {{"stream", in.stream},
                {"workload", in.header.workload},
                {"scene", in.header.scene_source},
                {"width", result.layout.width},
                {"height", result.layout.height},
                {"frames", result.single_trace_ns.size()},
                {"rays", result.rays}};
  j["device_set"] = device_set_json(*in.set);
  j["hardware"] = nlohmann::ordered_json::array();
  for (size_t i = 0; i < in.configs->configs().size(); ++i) {
    const HwConfig& c = in.configs->configs()[i];
    j["hardware"].push_back({{"index", i},
                             {"label", in.configs->labels()[i]},
                             {"name", c.name},
                             {"rt_units", c.rt_units},
                             {"clock_ghz", c.clock_ghz}});
  }
  j["summary"] = nlohmann::ordered_json::array();
  for (const StrategySummary& s : in.summaries) j["summary"].push_back(summary_json(s));
  j["single_device_trace_ns"] = result.single_trace_ns;
  j["runs"] = nlohmann::ordered_json::array();
  for (const StrategyRun& run : result.runs) {
    nlohmann::ordered_json frames = nlohmann::ordered_json::array();
    for (const FrameRecord& r : run.frames) frames.push_back(frame_json(r));
    j["runs"].push_back({{"strategy", strategy_name(run.strategy)}, {"frames", frames}});
  }
  j["host"] = {{"seconds", in.host_seconds}};
  return j;
}

std::string frames_csv(const MultiRunResult& result) {
  std::string out =
      "strategy,frame,frame_ns,single_ns,speedup,max_deviation_pct,copy_ns,copy_overhead_ns,"
      "copy_bytes\n";
  for (const StrategyRun& run : result.runs)
    for (const FrameRecord& r : run.frames)
      out += fmt::format("{},{},{:.1f},{:.1f},{:.4f},{:.3f},{:.1f},{:.1f},{}\n",
                         strategy_name(run.strategy), r.frame, r.timing.frame_ns, r.single_ns,
                         r.speedup, r.max_deviation_pct, r.timing.copy_ns,
                         r.timing.copy_overhead_ns, r.timing.copy_bytes);
  return out;
}

std::string devices_csv(const MultiRunResult& result) {
  std::string out =
      "strategy,frame,device,hardware,region_begin,region_end,pixels,samples,rays,cycles,cost,"
      "start_ns,trace_ns,end_ns,copy_in_ns,copy_out_ns,idle_ns\n";
  for (const StrategyRun& run : result.runs)
    for (const FrameRecord& r : run.frames)
      for (size_t d = 0; d < r.devices.size(); ++d) {
        const DeviceFrame& x = r.devices[d];
        const DeviceTiming& t = x.timing;
        out += fmt::format(
            "{},{},{},{},{},{},{},{},{},{},{:.0f},{:.1f},{:.1f},{:.1f},{:.1f},"
            "{:.1f},{:.1f}\n",
            strategy_name(run.strategy), r.frame, d, x.hardware, x.region.begin, x.region.end,
            x.pixels, x.samples, x.rays, x.cycles, x.cost, t.start_ns, t.trace_ns, t.end_ns,
            t.copy_in_ns, t.copy_out_ns, t.idle_ns);
      }
  return out;
}

void write_multi_report(const std::string& dir, const ReportInput& in, bool with_chart) {
  std::filesystem::create_directories(dir);
  write_file_atomic(dir + "/report.json", multi_report_json(in).dump(1) + "\n");
  write_file_atomic(dir + "/frames.csv", frames_csv(*in.result));
  write_file_atomic(dir + "/devices.csv", devices_csv(*in.result));
  write_file_atomic(dir + "/report.md", multi_report_markdown(in, with_chart));
}

}  // namespace rtsim::multi
