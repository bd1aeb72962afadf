#include "reports/trace_step.h"

#include <cstdio>
#include <filesystem>

#include <fmt/core.h>

#include "model/sc/sim_report.h"
#include "reports/page_util.h"
#include "reports/phase_progress.h"
#include "traces/output_file.h"
#include "traces/error.h"
#include "traces/hash.h"
#include "traces/stream.h"
#include "traces/text_table.h"
#include "workloads/pipeline/summary.h"
#include "workloads/pipeline/trace.h"

namespace rtsim::reports {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

Json trace_request_json(const TraceRequest& r) {
  Json j;
  bool file = fs::is_regular_file(r.workload);
  j["workload"] = file ? fs::absolute(r.workload).lexically_normal().string() : r.workload;
  if (file) {
    std::string text = read_file(r.workload);
    j["spec_hash"] = text_hash(text);
  }
  j["resolution"] = r.resolution;
  j["frames"] = r.frames;
  j["seed"] = r.seed ? Json(*r.seed) : Json();
  j["scene"] = r.scene;
  for (auto [key, value] : {std::pair{"camera", &r.camera}, {"look_at", &r.look_at}, {"up", &r.up}})
    if (!value->empty()) j[key] = *value;
  if (r.camera_index) j["camera_index"] = *r.camera_index;
  if (r.fov) j["fov"] = *r.fov;
  return j;
}

namespace {

Json summary_json(const pipeline::RunSummary& s) {
  Json passes = Json::array();
  for (int p = 0; p < pipeline::kPassCount; ++p) {
    const pipeline::PassSummary& ps = s.passes[size_t(p)];
    auto id = pipeline::PassId(p);
    std::string why = ps.reason.empty() ? "nothing to do" : ps.reason;
    passes.push_back({{"pass", pipeline::pass_name(id)},
                      {"ray_type", ray_type_name(pipeline::pass_ray_type(id))},
                      {"rays", ps.rays},
                      {"alpha_rays", ps.alpha_rays},
                      {"budget_per_frame", ps.budget},
                      {"frames_skipped", ps.frames_skipped},
                      {"skipped", ps.rays == 0},
                      {"reason", ps.rays == 0 || ps.frames_skipped > 0 ? why : ""}});
  }
  return {{"workload", s.workload},
          {"scene", s.scene_source},
          {"triangles", s.triangles},
          {"width", s.width},
          {"height", s.height},
          {"frames", s.frames},
          {"lights", s.lights},
          {"surfels", s.surfels},
          {"rays", s.total_rays()},
          {"passes", passes},
          {"seconds",
           {{"load", s.load_seconds}, {"build", s.build_seconds}, {"trace", s.trace_seconds}}}};
}

}  // namespace

TraceOutcome read_trace_dir(const std::string& dir) {
  std::string path = dir + "/trace.json";
  if (!fs::exists(path)) throw_input_error(dir, "", "not a trace folder (no trace.json)");
  TraceOutcome out;
  out.summary = read_json_file(path, kTraceSchema);
  using K = JsonKind;  // what runs and their reports read of it
  require_fields(out.summary, path,
                 {{"request", K::Present},
                  {"workload", K::String},
                  {"scene", K::String},
                  {"rays", K::Count},
                  {"triangles", K::Count},
                  {"width", K::Count},
                  {"height", K::Count},
                  {"frames", K::Count},
                  {"lights", K::Count},
                  {"surfels", K::Count},
                  {"passes", K::Array},
                  {"passes.*.pass", K::String},
                  {"passes.*.ray_type", K::String},
                  {"passes.*.rays", K::Count},
                  {"passes.*.budget_per_frame", K::Count},
                  {"passes.*.skipped", K::Bool},
                  {"passes.*.reason", K::String}});
  out.dir = dir;
  out.stream = dir + "/rays.rays";
  if (!fs::exists(out.stream)) throw_input_error(out.stream, "", "missing");
  if (fs::exists(dir + "/preview.png")) out.preview = dir + "/preview.png";
  return out;
}

bool is_stream_file(const std::string& path) {
  return fs::path(path).extension() == ".rays" && !fs::is_directory(path);
}

Json stream_summary(const std::string& stream) {
  StreamHeader h = RayStreamReader(stream).header();
  return {{"schema", kTraceSchema},
          {"request", {{"stream", fs::absolute(stream).lexically_normal().string()}}},
          {"workload", h.workload},
          {"scene", h.scene_source},
          {"triangles", Json()},
          {"width", h.width},
          {"height", h.height},
          {"frames", h.frame_count},
          {"lights", Json()},
          {"surfels", Json()},
          {"rays", h.total_rays()},
          {"passes", Json::array()},
          {"notes", Json::array({"read from the ray stream " + stream +
                                 ": its header records no passes, triangles or lights"})},
          {"stream", stream}};
}

TraceOutcome read_stream_trace(const std::string& stream) {
  return {"", stream, "", stream_summary(stream)};
}

TraceOutcome read_trace_source(const std::string& path) {
  return is_stream_file(path) ? read_stream_trace(path) : read_trace_dir(path);
}

bool trace_is_current(const TraceRequest& request, const std::string& dir) {
  if (!fs::exists(dir + "/trace.json") || !fs::exists(dir + "/rays.rays")) return false;
  return read_trace_dir(dir).summary["request"] == trace_request_json(request);
}

TraceOutcome trace_into(const TraceRequest& request, const std::string& dir, bool quiet) {
  Json wanted = trace_request_json(request);
  if (trace_is_current(request, dir)) {
    TraceOutcome old = read_trace_dir(dir);
    if (!quiet)
      fmt::print("trace      reusing {} ({} rays)\n", dir,
                 whole_number(old.summary["rays"].get<uint64_t>()));
    return old;
  }
  create_output_folder(dir);
  pipeline::WorkloadSpec spec = pipeline::load_workload(request.workload);
  pipeline::apply_overrides(
      spec, pipeline::make_overrides({request.resolution, request.frames, request.seed,
                                      request.scene, request.camera, request.look_at, request.up,
                                      request.camera_index, request.fov}));
  pipeline::TraceOptions options;
  options.output = dir + "/rays.rays";
  options.preview = dir + "/preview.png";
  options.generator = "rtsim " RTSIM_VERSION;
  if (!quiet) {
    fmt::print("trace      {} at {}x{}, {} frame(s), into {}\n", spec.name, spec.width, spec.height,
               spec.frames, dir);
    std::fflush(stdout);  // before the progress lines on stderr, also in a pipe
    options.progress = trace_progress();
  }
  pipeline::TraceResult result = pipeline::trace_workload(spec, options);
  if (!quiet)
    for (const std::string& note : result.notes) fmt::print(stderr, "trace: {}\n", note);
  Json summary;
  summary["schema"] = kTraceSchema;
  summary["request"] = wanted;
  Json pipeline_summary = summary_json(result.summary);
  for (auto& [key, value] : pipeline_summary.items()) summary[key] = value;
  summary["notes"] = result.notes;
  std::string mix = pipeline::ray_mix_note(result.summary);
  summary["ray_mix"] = mix.empty() ? Json() : Json(mix);
  summary["stream"] = "rays.rays";
  summary["preview"] = "preview.png";
  write_file_atomic(dir + "/trace.json", summary.dump(2) + "\n");
  if (!quiet)
    fmt::print(
        "trace      {} rays of {} on {} ({} triangles) in {:.1f} s\n",
        whole_number(uint64_t(result.summary.total_rays())), request.workload,
        result.summary.scene_source, whole_number(uint64_t(result.summary.triangles)),
        result.summary.load_seconds + result.summary.build_seconds + result.summary.trace_seconds);
  std::fflush(stdout);
  TraceOutcome out{dir, options.output, options.preview, summary};
  return out;
}

}  // namespace rtsim::reports
