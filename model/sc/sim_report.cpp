#include "model/sc/sim_report.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "model/energy/design_energy.h"
#include "model/verify/arbiter.h"
#include "traces/error.h"
#include "traces/output_file.h"

namespace rtsim {
namespace {

using Json = nlohmann::ordered_json;

// A cache level's stats prefix: "mem.NAME".
std::string level_stats(const MemoryLevelConfig& level) {
  return "mem." + level.name;
}

Json latency_json(const LatencyHistogram& h) {
  return {{"p50", h.percentile(0.50)},
          {"p95", h.percentile(0.95)},
          {"p99", h.percentile(0.99)},
          {"mean", h.mean()},
          {"max", h.max()}};
}

// l1_hit_rate: the unit's first level; l2_hit_rate: the level above DRAM.
Json ray_type_json(const RayTypeStats& s, const StatsRegistry& r, const std::string& p,
                   const HwConfig& c) {
  Json warps = latency_json(s.warp_latency);
  warps["warps"] = s.warp_latency.count();
  Json out = {{"rays", s.rays},
              {"hits", s.hits},
              {"latency_cycles", latency_json(s.latency)},
              {"warp_latency_cycles", warps},
              {"nodes_per_ray", r.value(p + ".nodes_per_ray")},
              {"triangles_per_ray", r.value(p + ".triangles_per_ray")},
              {"l1_hit_rate", r.value(p + "." + level_stats(first_level(c)) + ".hit_rate")},
              {"l2_hit_rate", r.value(p + "." + level_stats(last_level(c)) + ".hit_rate")},
              {"dram_bytes_per_ray", r.value(p + ".dram_bytes_per_ray")},
              {"stack_spills_per_ray", r.value(p + ".stack_spills_per_ray")}};
  if (r.has(p + ".instances_per_ray")) out["instances_per_ray"] = r.value(p + ".instances_per_ray");
  return out;
}

Json mismatch_json(const Mismatch& m) {
  return {{"ray", m.index},
          {"class", mismatch_class_name(m.verdict.cls)},
          {"right", right_side_name(m.verdict.right)},
          {"embree_prim", m.embree.prim},
          {"model_prim", m.model_prim},
          {"embree_t", m.embree.t},
          {"model_t", m.model.t}};
}

Json verify_json(const VerifyReport& v) {
  Json classes = Json::object();
  for (int c = 0; c < kMismatchClassCount; ++c)
    if (v.by_class[c]) classes[mismatch_class_name(MismatchClass(c))] = v.by_class[c];
  Json examples = Json::array(), unexplained = Json::array();
  for (const Mismatch& m : v.examples) examples.push_back(mismatch_json(m));
  for (const Mismatch& m : v.unexplained_examples) unexplained.push_back(mismatch_json(m));
  return {{"rays", v.rays},
          {"agree", v.agree},
          {"mismatches", v.mismatches()},
          {"unexplained", v.unexplained()},
          {"by_class", classes},
          {"examples", examples},
          {"unexplained_examples", unexplained}};
}

// The busiest crossbar link (0 without a crossbar).
// Over every crossbar link of every level (mem.NAME[.gK].xbar.*.utilisation).
double busiest_link(const StatsRegistry& r) {
  const std::string suffix = ".utilisation";
  double most = 0;
  for (const std::string& name : r.names())
    if (name.find(".xbar.") != std::string::npos && name.size() > suffix.size() &&
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      most = std::max(most, r.value(name));
  return most;
}

Json utilisation_json(const HwConfig& c, const StatsRegistry& r) {
  Json units = Json::object();
  for (uint32_t i = 0; i < c.rt_units; ++i) {
    std::string p = "rt" + std::to_string(i);
    units[p] = {{"box", r.value(p + ".box.utilisation")},
                {"triangle", r.value(p + ".triangle.utilisation")},
                {"control", r.value(p + ".control.utilisation")},
                {"l1_port", r.value(level_stats(first_level(c)) + "." + p + ".port_utilisation")},
                {"ray_slots", r.value(p + ".slot_occupancy")}};
  }
  auto mean = [&](const char* suffix) { return r.units_sum(c.rt_units, suffix) / c.rt_units; };
  double first_port_mean = 0;  // summed unit by unit, as units_sum does
  for (uint32_t i = 0; i < c.rt_units; ++i)
    first_port_mean +=
        r.value(level_stats(first_level(c)) + ".rt" + std::to_string(i) + ".port_utilisation");
  first_port_mean /= c.rt_units;
  Json means = {{"box", mean(".box.utilisation")},
                {"triangle", mean(".triangle.utilisation")},
                {"control", mean(".control.utilisation")},
                {"l1_port", first_port_mean},
                {"ray_slots", r.value("rt.slot_occupancy")}};
  // Two levels: the instance transform units too.
  if (r.has("rt0.transform.utilisation")) {
    for (auto& [name, unit] : units.items())
      unit["transform"] = r.value(name + ".transform.utilisation");
    means["transform"] = mean(".transform.utilisation");
  }
  // A shader model: the SMs' warp schedulers beside the RT units.
  if (r.has("shader.utilisation")) {
    for (auto& [name, unit] : units.items()) unit["shader"] = r.value(name + ".shader.utilisation");
    means["shader"] = r.value("shader.utilisation");
  }
  return {{"mean", means},
          {"units", units},
          {"dispatch", r.value("dispatch.utilisation")},
          {"l2_port", r.value(level_stats(last_level(c)) + ".port_utilisation")},
          {"xbar_busiest_link", busiest_link(r)},
          {"dram", r.value("dram.utilisation")}};
}

// What limits the design: the throughput resources by utilisation, the busiest first. Below
// half busy, none of them does: rays wait on latency (memory), which the slots' occupancy shows.
Json bottleneck_json(const Json& u) {
  static const std::pair<const char*, const char*> kResources[] = {
      {"box", "box-test units"},
      {"triangle", "triangle-test units"},
      {"transform", "instance transform units"},
      {"control", "traversal issue"},
      {"shader", "SM warp schedulers (shading)"},
      {"l1_port", "L1 data ports"},
      {"l2_port", "L2 data ports"},
      {"xbar_busiest_link", "busiest crossbar link"},
      {"dram", "DRAM data bus"},
      {"dispatch", "ray dispatch"}};
  const Json none = Json::object();
  const Json& mean = u.contains("mean") ? u["mean"] : none;
  auto value = [&](const char* key) {
    const Json& v = mean.contains(key) ? mean[key] : u.contains(key) ? u[key] : none;
    return v.is_number() ? v.get<double>() : -1.0;
  };
  std::vector<std::pair<double, const char*>> busy;
  for (const auto& [key, label] : kResources)
    if (value(key) >= 0) busy.push_back({value(key), label});
  std::stable_sort(busy.begin(), busy.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  if (busy.size() < 2) return {{"text", Json()}, {"resource", Json()}, {"utilisation", Json()}};
  auto pct = [](double x) { return fmt::format("{:.0f}%", 100 * x); };
  std::string text =
      busy[0].first >= 0.5
          ? fmt::format("{} {} busy; next: {} {}", busy[0].second, pct(busy[0].first),
                        busy[1].second, pct(busy[1].first))
          : fmt::format(
                "latency: no unit, port or bus is half busy (busiest: {} {}; ray slots {} "
                "occupied)",
                busy[0].second, pct(busy[0].first), pct(std::max(0.0, value("ray_slots"))));
  return {{"text", text}, {"resource", busy[0].second}, {"utilisation", busy[0].first}};
}

// The shader side: where the SMs' scheduler time went, what waiting for it cost the RT units,
// and what shading read; null without a shader model.
Json shader_json(const HwConfig& c, const StatsRegistry& r) {
  if (c.shader.model == ShaderModel::None) return Json();
  Json by_type = Json::object();
  for (int t = 0; t < kRayTypeCount; ++t) {
    std::string name = ray_type_name(RayType(t));
    std::string key = "shader.type." + name + ".busy_cycles";
    if (r.has(key)) by_type[name] = r.value(key);
  }
  return {
      {"model", shader_model_name(c.shader.model)},
      {"busy_cycles", r.value("shader.busy_cycles")},
      {"raygen_cycles", r.value("shader.raygen_cycles")},
      {"hit_cycles", r.value("shader.hit_cycles")},
      {"miss_cycles", r.value("shader.miss_cycles")},
      {"busy_cycles_by_type", by_type},
      {"utilisation", r.value("shader.utilisation")},
      {"busy_cycles_per_ray", r.value("shader.busy_cycles_per_ray")},
      {"mean_trace_delay", r.value("shader.mean_trace_delay")},
      {"slot_wait_cycles", r.value("shader.slot_wait_cycles")},
      {"read_bytes", r.value("shader.read_bytes")},
      {"reads_l1_miss_rate", r.value("shader.reads." + level_stats(first_level(c)) + ".miss_rate")},
      {"reads_dram_bytes_per_ray", r.value("shader.reads.dram_bytes_per_ray")}};
}

// l1_*: the unit's first level, l2_*: the level above DRAM (the same in a one-level hierarchy);
// levels: each level from the unit outwards.
Json memory_json(const HwConfig& c, const StatsRegistry& r) {
  Json levels = Json::array();
  for (const MemoryLevelConfig& level : c.memory) {
    std::string p = level_stats(level);
    levels.push_back({{"name", level.name},
                      {"scope", scope_name(level)},
                      {"accesses", r.value(p + ".accesses")},
                      {"hit_rate", r.value(p + ".hit_rate")},
                      {"served_rate", r.value(p + ".served_rate")},
                      {"compulsory_share", r.value(p + ".compulsory_share")}});
  }
  std::string first = level_stats(first_level(c)), last = level_stats(last_level(c));
  return {{"levels", levels},
          {"l1_hit_rate", r.value(first + ".hit_rate")},
          {"l2_hit_rate", r.value(last + ".hit_rate")},
          {"l1_served_rate", r.value(first + ".served_rate")},
          {"l2_served_rate", r.value(last + ".served_rate")},
          {"l1_compulsory_share", r.value(first + ".compulsory_share")},
          {"l2_compulsory_share", r.value(last + ".compulsory_share")},
          {"dram_bytes", r.value("dram.bytes")},
          {"dram_bytes_per_ray", r.value("dram.bytes_per_ray")},
          {"dram_bytes_per_cycle", r.value("dram.bytes_per_cycle")}};
}

// Per measured frame (only for more than one): what each frame cost, from the dispatch of its
// first ray to that of the next frame's.
Json frames_json(const RtSimulator& sim) {
  std::vector<RtSimulator::FrameStats> frames = sim.frame_stats();
  Json list = Json::array();
  if (frames.size() < 2) return list;
  for (const RtSimulator::FrameStats& f : frames)
    list.push_back({{"frame", f.frame},
                    {"start_cycle", f.start},
                    {"cycles", f.stats.value("cycles")},
                    {"rays", f.stats.value("dispatch.rays")},
                    {"memory", memory_json(sim.config(), f.stats)},
                    {"dram_utilisation", f.stats.value("dram.utilisation")}});
  return list;
}

// Bytes per treelet: budgeted (nodes, or nodes and leaf triangles), nodes and triangles.
Json treelet_sizes_json(const TreeletStats& t) {
  double n = std::max<double>(t.count, 1);
  return {{"budget_bytes", t.budget_bytes},
          {"budget_counts", treelet_budget_name(t.budget)},
          {"oversized", t.oversized},
          {"mean_bytes", t.total_bytes / n},
          {"max_bytes", t.max_bytes},
          {"mean_node_bytes", t.node_bytes / n},
          {"mean_triangle_bytes", t.triangle_bytes / n},
          {"max_triangle_bytes", t.max_triangle_bytes}};
}

// One level: its figures. Two: the sums over the levels (triangles: the unique ones), and each
// level's nodes, bytes and treelets. node_bytes and leaf_bytes: one internal node and one leaf
// block (a triangle record; xe6: a 64-byte quad) of the triangles' level.
Json bvh_json(const BvhView& bvh) {
  const BvhImage& top = *bvh.top;
  if (!bvh.two_level())
    return {{"description", describe(top.config)},
            {"levels", 1},
            {"nodes", top.node_count},
            {"triangles", top.triangle_count},
            {"treelets", top.treelets.count},
            {"treelet_sizes", treelet_sizes_json(top.treelets)},
            {"bytes", top.total_bytes()},
            {"node_bytes", top.node_size},
            {"leaf_bytes", top.triangle_stride},
            {"node_padding_bytes", top.node_padding_bytes()}};
  // The top levels: frame 0's, and with moving instances each later frame's, which a builder
  // writes anew every frame.
  std::vector<const BvhImage*> tops{&top};
  if (bvh.frame_tops)
    for (const BvhImage& t : *bvh.frame_tops) tops.push_back(&t);
  uint64_t top_nodes = 0, top_bytes = 0, top_padding = 0;
  Json per_frame = Json::array();
  for (const BvhImage* t : tops) {
    top_nodes += t->node_count;
    top_bytes += t->total_bytes();
    top_padding += t->node_padding_bytes();
    per_frame.push_back({{"nodes_written", t->node_count}, {"bytes_written", t->total_bytes()}});
  }
  Json top_json = {{"nodes", top_nodes},
                   {"bytes", top_bytes},
                   {"treelets", bvh.bottom->front().treelet_base},
                   {"node_bytes", top.node_size},
                   {"leaf_bytes", top.triangle_stride}};
  if (bvh.frame_tops) top_json["per_frame"] = per_frame;
  uint64_t nodes = 0, triangles = 0, bytes = 0, padding = 0;
  for (const BvhImage& b : *bvh.bottom) {
    nodes += b.node_count;
    triangles += b.triangle_count;
    bytes += b.total_bytes();
    padding += b.node_padding_bytes();
  }
  return {{"description", describe(bvh.bottom->front().config)},
          {"levels", 2},
          {"nodes", nodes + top_nodes},
          {"triangles", triangles},
          {"instances", top.triangle_count},
          {"treelets", bvh.treelet_count()},
          {"bytes", bytes + top_bytes},
          {"node_bytes", bvh.bottom->front().node_size},
          {"leaf_bytes", bvh.bottom->front().triangle_stride},
          {"node_padding_bytes", padding + top_padding},
          {"top", top_json},
          {"bottom",
           {{"meshes", bvh.bottom->size()},
            {"nodes", nodes},
            {"bytes", bytes},
            {"treelets", bvh.treelet_count() - bvh.bottom->front().treelet_base}}}};
}

}  // namespace

Json sim_stats_json(const RtSimulator& sim, const StatsRegistry& r, const SimRunInfo& info) {
  const HwConfig& c = sim.config();
  Json doc;
  doc["schema"] = kSimStatsSchema;
  doc["config_name"] = c.name;
  doc["input"] = {{"stream", info.stream},
                  {"scene", info.header.scene_source},
                  {"workload", info.header.workload},
                  {"width", info.header.width},
                  {"height", info.header.height}};
  if (!info.ray_types.empty()) doc["input"]["ray_types"] = info.ray_types;
  if (info.bvh) doc["bvh"] = bvh_json(*info.bvh);
  doc["summary"] = {{"mode", traversal_mode_name(c.rt.mode)},
                    {"rays", sim.rays()},
                    {"cycles", sim.cycles()},
                    {"rays_per_cycle", r.value("rays_per_cycle")},
                    {"clock_ghz", c.clock_ghz},
                    {"mrays_per_second", r.value("mrays_per_second")},
                    {"warmup_rays", c.sim.warmup_rays},
                    {"warmup_frames", c.sim.warmup_frames},
                    {"measured_from_cycle", sim.measured_from()}};
  Json types = Json::object();
  for (int t = 0; t < kRayTypeCount; ++t) {
    const RayTypeStats& s = sim.collected().by_type()[t];
    if (s.rays == 0) continue;
    std::string name = ray_type_name(RayType(t));
    types[name] = ray_type_json(s, r, "type." + name, c);
  }
  doc["ray_types"] = types;
  doc["memory"] = memory_json(c, r);
  doc["frames"] = frames_json(sim);
  doc["utilisation"] = utilisation_json(c, r);
  doc["bottleneck"] = bottleneck_json(doc["utilisation"]);
  doc["shader"] = shader_json(c, r);
  doc["energy"] = design_energy_json(design_energy(c, r));
  // Coherence figures exist only in the mode that produces them; elsewhere they are null.
  bool packet = c.rt.mode == TraversalMode::Packet, treelet = c.rt.mode == TraversalMode::Treelet;
  auto when = [&](bool applies, const char* name) {
    return applies ? Json(r.value(name)) : Json();
  };
  doc["coherence"] = {
      {"simd_efficiency", when(packet, "rt.simd_efficiency")},
      {"distinct_nodes_per_warp_step", when(packet, "rt.distinct_nodes_per_warp_step")},
      {"treelet_queue_occupancy", when(treelet, "treelet_queues.occupancy")},
      {"treelet_queue_mean_rays", when(treelet, "treelet_queues.mean_queued")},
      {"treelet_queue_max_rays", when(treelet, "treelet_queues.max_queued")},
      {"rays_per_treelet_visit", when(treelet, "treelet_queues.rays_per_visit")}};
  // Two levels: transforms, and each level's nodes and misses per ray.
  bool levels = r.has("bvh.instances_per_ray");
  for (const char* level : {"top", "bottom"}) {
    std::string key = level[0] == 't' ? "tlas_" : "blas_", stat = std::string("bvh.") + level;
    for (const char* name : {"nodes_per_ray", "dram_bytes_per_ray"})
      doc["coherence"][key + name] = when(levels, (stat + "." + name).c_str());
    doc["coherence"][key + "l1_miss_rate"] =
        when(levels, (stat + "." + level_stats(first_level(c)) + ".miss_rate").c_str());
    doc["coherence"][key + "l2_miss_rate"] =
        when(levels, (stat + "." + level_stats(last_level(c)) + ".miss_rate").c_str());
  }
  doc["coherence"]["instances_per_ray"] = when(levels, "bvh.instances_per_ray");
  double rays = double(std::max<uint64_t>(sim.rays(), 1));
  doc["stack"] = {{"spill_entries", r.value("rt.stack.spill_entries")},
                  {"refill_entries", r.value("rt.stack.refill_entries")},
                  {"spills_per_ray", r.value("rt.stack.spill_entries") / rays},
                  {"refill_l1_reads", r.value(level_stats(first_level(c)) + ".local_reads")},
                  {"refill_l1_misses", r.value(level_stats(first_level(c)) + ".local_misses")},
                  {"refill_l2_misses", r.value(level_stats(last_level(c)) + ".local_misses")},
                  {"l1_writeback_bytes", r.value(level_stats(first_level(c)) + ".writeback_bytes")},
                  {"l2_writeback_bytes", r.value(level_stats(last_level(c)) + ".writeback_bytes")},
                  {"dram_write_bytes", r.value("dram.write_bytes")}};
  doc["verify"] = info.verify ? verify_json(*info.verify) : Json{{"skipped", true}};
  const PixelBuffers& px = sim.collected().pixels();
  if (!px.cycles.empty())
    doc["pixel_buffers"] = {{"width", px.width},
                            {"height", px.height},
                            {"format",
                             "float32 little-endian, row-major, summed over the "
                             "pixel's rays of all frames"},
                            {"files",
                             {{"cycles", "pixel_cycles.f32"},
                              {"nodes", "pixel_nodes.f32"},
                              {"dram_bytes", "pixel_dram_bytes.f32"}}}};
  doc["stats"] = r.to_json();
  doc["config"] = resolved_json(c);
  doc["host"] = {{"seconds", info.host_seconds},
                 {"rays_per_second", info.host_seconds > 0 ? sim.rays() / info.host_seconds : 0}};
  return doc;
}

void write_file_atomic(const std::string& path, const void* data, size_t size) {
  OutputFile output(path);
  int error = 0;  // the first failure's errno
  if (FILE* file = std::fopen(output.write_path().c_str(), "wb")) {
    if (std::fwrite(data, 1, size, file) != size || std::fflush(file) != 0) error = errno;
    if (std::fclose(file) != 0 && error == 0) error = errno;
  } else {
    error = errno;
  }
  if (error == 0 && !output.commit()) error = errno;
  if (error == 0) return;
  output.discard();
  throw_input_error(path, "", std::string("cannot write: ") + std::strerror(error));
}

void write_file_atomic(const std::string& path, const std::string& bytes) {
  write_file_atomic(path, bytes.data(), bytes.size());
}

std::vector<std::string> sim_result_files(const std::string& dir) {
  std::vector<std::string> files;
  for (const char* name :
       {"stats.json", "config.toml", "pixel_cycles.f32", "pixel_nodes.f32", "pixel_dram_bytes.f32"})
    files.push_back(dir + "/" + name);
  return files;
}

Json write_sim_results(const std::string& dir, const RtSimulator& sim, const SimRunInfo& info) {
  create_output_folder(dir);
  StatsRegistry stats;
  sim.report(stats);
  Json doc = sim_stats_json(sim, stats, info);
  const PixelBuffers& px = sim.collected().pixels();
  auto write_floats = [&dir](const char* name, const std::vector<float>& v) {
    write_file_atomic(dir + "/" + name, v.data(), v.size() * sizeof(float));
  };
  if (!px.cycles.empty()) {
    write_floats("pixel_cycles.f32", px.cycles);
    write_floats("pixel_nodes.f32", px.nodes);
    write_floats("pixel_dram_bytes.f32", px.dram_bytes);
  }
  write_file_atomic(dir + "/config.toml", resolved_toml(sim.config()));
  write_file_atomic(dir + "/stats.json", doc.dump(2) + "\n");
  return doc;
}

}  // namespace rtsim
