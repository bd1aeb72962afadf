#include "reports/report_doc.h"

#include "model/fidelity/sampled_level.h"
#include "model/sc/rt_simulator.h"

namespace rtsim::reports {
namespace {

using Json = nlohmann::ordered_json;

Json estimate_value(const Estimate& e) {
  return e.known ? Json(e.value) : Json();
}

double sum_units(const Json& counters, uint32_t units, const std::string& suffix) {
  double total = 0;
  for (uint32_t i = 0; i < units; ++i) {
    std::string key = "rt" + std::to_string(i) + suffix;
    if (counters.contains(key)) total += counters[key].get<double>();
  }
  return total;
}

Json workload_json(const Json& trace, const FidelityResult& f) {
  Json per_type = Json::object();
  for (int t = 0; t < kRayTypeCount; ++t)
    if (f.types[t].rays) per_type[ray_type_name(RayType(t))] = f.types[t].rays;
  return {{"name", trace["workload"]},
          {"scene", trace["scene"]},
          {"triangles", trace["triangles"]},
          {"width", trace["width"]},
          {"height", trace["height"]},
          {"frames", trace["frames"]},
          {"lights", trace["lights"]},
          {"surfels", trace["surfels"]},
          {"rays", f.rays},
          {"rays_per_type", per_type},
          {"passes", trace["passes"]},
          {"ray_mix", trace.contains("ray_mix") ? trace["ray_mix"] : Json()}};
}

Json hardware_json(const ReportInputs& in) {
  const HwConfig& c = *in.config;
  auto cache = [](const CacheConfig& k) {
    return Json{{"size_bytes", k.size_bytes},
                {"line_bytes", k.line_bytes},
                {"ways", k.ways},
                {"hit_latency", k.hit_latency},
                {"mshrs", k.mshrs}};
  };
  Json levels = Json::array();
  for (const MemoryLevelConfig& level : c.memory) {
    Json l = cache(level.cache);
    l["name"] = level.name;
    l["scope"] = scope_name(level);
    l["fill"] = level.fill == LevelFill::Victim ? "victim" : "miss";
    l["instances"] = level_instances(level, c.rt_units);
    levels.push_back(l);
  }
  return {{"name", c.name},
          {"description", c.description},
          {"config_file", in.config_file},
          {"sets", in.sets},
          {"clock_ghz", c.clock_ghz},
          {"rt_units", c.rt_units},
          {"mode", traversal_mode_name(c.rt.mode)},
          {"ray_slots", ray_slots(c)},
          {"levels", levels},
          {"l1", cache(first_level(c).cache)},
          {"l2", cache(last_level(c).cache)},
          {"dram",
           {{"model", c.dram_model == DramModel::Banked ? "banked" : "simple"},
            {"bytes_per_cycle", c.dram.bytes_per_cycle},
            {"latency", c.dram.latency}}},
          {"bvh", describe(c.bvh)},
          {"on_chip_bytes", on_chip_bytes(c)},
          {"resolved", resolved_json(c)}};
}

Json timing_json(const FidelityResult& f, const Json& stats) {
  Json t = {{"level", fidelity_level_name(f.level)},
            {"time_model", f.time_model},
            {"caveat", f.caveat.empty() ? Json() : Json(f.caveat)},
            {"rays", f.rays},
            {"cycles", estimate_value(f.cycles)},
            {"cycles_ci95", f.cycles.known ? Json(f.cycles.ci95) : Json()},
            {"clock_ghz", f.clock_ghz},
            {"mrays_per_second", f.cycles.known ? Json(f.mrays_per_second()) : Json()},
            {"rays_per_cycle", f.cycles.known ? Json(double(f.rays) / f.cycles.value) : Json()},
            {"host_seconds", f.host_seconds}};
  if (!stats.is_null()) t["rays_per_host_second"] = stats["host"]["rays_per_second"];
  t["bottleneck"] = stats.is_null()
                        ? Json{{"text", Json()}, {"resource", Json()}, {"utilisation", Json()}}
                        : stats["bottleneck"];
  return t;
}

Json bandwidth_json(const FidelityResult& f, const Json& stats, const HwConfig& c) {
  double rays = double(std::max<uint64_t>(f.rays, 1));
  Json b = {{"l1_hit_rate", estimate_value(f.first_level_hit_rate())},
            {"l2_hit_rate", estimate_value(f.last_level_hit_rate())},
            {"dram_bytes", estimate_value(f.dram_bytes)},
            {"dram_bytes_per_ray", f.dram_bytes.known ? Json(f.dram_bytes.value / rays) : Json()},
            {"l1_bytes_per_ray", Json()},
            {"l2_bytes_per_ray", Json()},
            {"dram_bytes_per_cycle", Json()},
            {"dram_utilisation", Json()},
            {"l1_served_rate", Json()},
            {"l2_served_rate", Json()},
            {"l1_compulsory_share", Json()},
            {"l2_compulsory_share", Json()}};
  Json by_type = Json::object();
  for (int t = 0; t < kRayTypeCount; ++t) {
    const TypeEstimate& e = f.types[t];
    if (!e.rays) continue;
    by_type[ray_type_name(RayType(t))] = {
        {"dram_bytes_per_ray", estimate_value(e.dram_bytes_per_ray)}};
  }
  if (!stats.is_null()) {
    const Json& counters = stats["stats"]["counters"];
    b["l1_bytes_per_ray"] = sum_units(counters, c.rt_units, ".fetch_bytes") / rays;
    const std::string first = "mem." + first_level(c).name, last = "mem." + last_level(c).name;
    b["l2_bytes_per_ray"] = counters[first + ".bytes_below"].get<double>() / rays;
    b["dram_bytes_per_cycle"] = stats["memory"]["dram_bytes_per_cycle"];
    b["dram_utilisation"] = stats["utilisation"]["dram"];
    for (const char* key :
         {"l1_served_rate", "l2_served_rate", "l1_compulsory_share", "l2_compulsory_share"})
      b[key] = stats["memory"][key];
    if (stats["memory"].contains("levels")) b["levels"] = stats["memory"]["levels"];
    for (auto& [name, entry] : by_type.items()) {
      double n = counters["type." + name + ".rays"].get<double>();
      entry["l1_bytes_per_ray"] =
          counters["type." + name + "." + first + ".accesses"].get<double>() *
          block_bytes(first_level(c).cache) / n;
      entry["l2_bytes_per_ray"] =
          counters["type." + name + "." + last + ".accesses"].get<double>() *
          last_level(c).cache.line_bytes / n;
    }
  }
  b["by_type"] = by_type;
  return b;
}

// The DRAM section: the model and, from a cycle-level run with the banked DRAM, row buffer
// outcomes, read latency percentiles and per-channel utilisation (null where not known).
Json dram_json(const Json& stats, const HwConfig& c) {
  bool banked = c.dram_model == DramModel::Banked;
  Json d = {{"model", banked ? "banked" : "simple"},
            {"preset", banked ? Json(c.banked_dram.preset) : Json()},
            {"channels", banked ? Json(c.banked_dram.channels) : Json(1)},
            {"peak_gb_per_s",
             banked ? c.banked_dram.peak_gb_per_s() : c.dram.bytes_per_cycle * c.clock_ghz}};
  const char* derived[] = {"utilisation", "row_hit_rate", "row_conflict_rate", "mean_latency",
                           "queue_occupancy"};
  const char* counted[] = {"turnarounds", "refresh_stall_clocks", "latency_p50",
                           "latency_p90", "latency_p99",          "latency_max"};
  for (const char* key : derived) d[key] = Json();
  for (const char* key : counted) d[key] = Json();
  d["by_channel"] = Json::object();
  if (stats.is_null()) return d;
  const Json& counters = stats["stats"]["counters"];
  const Json& ratios = stats["stats"]["derived"];
  for (const char* key : derived)
    if (ratios.contains(std::string("dram.") + key)) d[key] = ratios[std::string("dram.") + key];
  for (const char* key : counted)
    if (counters.contains(std::string("dram.") + key))
      d[key] = counters[std::string("dram.") + key];
  for (uint32_t ch = 0; banked && ch < c.banked_dram.channels; ++ch) {
    std::string p = "dram.ch" + std::to_string(ch);
    d["by_channel"]["ch" + std::to_string(ch)] = {{"utilisation", ratios[p + ".utilisation"]},
                                                  {"busy_clocks", counters[p + ".busy_clocks"]}};
  }
  return d;
}

Json coherence_json(const FidelityResult& f, const Json& stats) {
  Json c = {{"nodes_per_ray", estimate_value(f.nodes_per_ray)},
            {"triangles_per_ray", estimate_value(f.triangles_per_ray)}};
  Json by_type = Json::object();
  for (int t = 0; t < kRayTypeCount; ++t) {
    const TypeEstimate& e = f.types[t];
    if (!e.rays) continue;
    std::string name = ray_type_name(RayType(t));
    by_type[name] = {{"nodes_per_ray", estimate_value(e.nodes_per_ray)},
                     {"triangles_per_ray", estimate_value(e.triangles_per_ray)}};
    if (!stats.is_null())
      by_type[name]["stack_spills_per_ray"] = stats["ray_types"][name]["stack_spills_per_ray"];
  }
  if (!stats.is_null()) {
    for (auto& [key, value] : stats["coherence"].items()) c[key] = value;
    c["stack_spills_per_ray"] = stats["stack"]["spills_per_ray"];
  }
  c["by_type"] = by_type;
  return c;
}

Json verification_json(const Json& stats, FidelityLevel level) {
  if (stats.is_null())
    return {{"skipped", true},
            {"reason", std::string("not run at the ") + fidelity_level_name(level) +
                           " fidelity level (rtsim verify checks any stream)"}};
  Json v = stats["verify"];
  if (v.contains("skipped")) return {{"skipped", true}, {"reason", "--no-verify"}};
  v["skipped"] = false;
  v["passed"] = v["unexplained"].get<uint64_t>() == 0;
  return v;
}

Json latency_json(const FidelityResult& f, const Json& stats, const Json& collected) {
  Json l = Json::object();
  for (int t = 0; t < kRayTypeCount; ++t) {
    if (!f.types[t].rays) continue;
    std::string name = ray_type_name(RayType(t));
    if (!stats.is_null())
      l[name] = stats["ray_types"][name]["latency_cycles"];
    else if (f.types[t].latency_mean.known)
      l[name] = {{"mean", f.types[t].latency_mean.value}};
  }
  Json out = {{"by_type", l}};
  out["histogram"] = collected.is_null() ? Json() : collected["latency_histogram"];
  return out;
}

Json hit_rates_json(const FidelityResult& f) {
  Json h = Json::object();
  for (int t = 0; t < kRayTypeCount; ++t) {
    const TypeEstimate& e = f.types[t];
    if (!e.rays || !e.first_level_hit_rate().known) continue;
    h[ray_type_name(RayType(t))] = {{"l1", e.first_level_hit_rate().value},
                                    {"l2", e.last_level_hit_rate().value}};
  }
  return {{"l1", estimate_value(f.first_level_hit_rate())},
          {"l2", estimate_value(f.last_level_hit_rate())},
          {"by_type", h}};
}

Json time_json(const FidelityResult& f, const Json& stats, const Json& collected) {
  Json share = Json::object();
  double total = 0;
  for (int t = 0; t < kRayTypeCount; ++t)
    if (f.types[t].latency_mean.known)
      total += f.types[t].latency_mean.value * double(f.types[t].rays);
  for (int t = 0; t < kRayTypeCount; ++t)
    if (f.types[t].latency_mean.known && total > 0)
      share[ray_type_name(RayType(t))] =
          f.types[t].latency_mean.value * double(f.types[t].rays) / total;
  Json out = {{"ray_time_share", share}};
  if (stats.is_null()) {
    out["utilisation"] = Json();
    out["timeline"] = Json();
    return out;
  }
  Json u = stats["utilisation"]["mean"];
  u["dram"] = stats["utilisation"]["dram"];
  u["dispatch"] = stats["utilisation"]["dispatch"];
  out["utilisation"] = u;
  out["timeline"] = collected["timeline"];
  if (stats.contains("shader")) out["shader"] = stats["shader"];
  return out;
}

}  // namespace

double on_chip_bytes(const HwConfig& c) {
  double stacks = double(c.rt.warps) * c.rt.warp_size * c.rt.stack.entries * c.rt.stack.entry_bytes;
  double bytes = double(c.rt_units) * stacks + ray_buffer_sram_bytes(c) + sort_buffer_bytes(c.sort);
  for (const MemoryLevelConfig& level : c.memory)
    bytes += double(level_instances(level, c.rt_units)) * double(level.cache.size_bytes);
  return bytes;
}

Json build_report(const ReportInputs& in) {
  const FidelityResult& f = in.run->fidelity;
  const Json& stats = in.run->stats;
  const Json& collected = in.run->collected;
  Json r;
  r["schema"] = kReportSchema;
  r["generator"] = "rtsim " RTSIM_VERSION;
  r["command"] = in.command;
  r["workload"] = workload_json(in.trace->summary, f);
  r["hardware"] = hardware_json(in);
  r["fidelity"] = f.to_json();
  r["timing"] = timing_json(f, stats);
  r["bandwidth"] = bandwidth_json(f, stats, *in.config);
  r["dram"] = dram_json(stats, *in.config);
  r["coherence"] = coherence_json(f, stats);
  r["verification"] = verification_json(stats, f.level);
  r["latency"] = latency_json(f, stats, collected);
  r["hit_rates"] = hit_rates_json(f);
  r["time"] = time_json(f, stats, collected);
  r["energy"] = stats.is_null() ? Json() : stats["energy"];  // from the cycle model's counts
  bool pixels = !stats.is_null() && stats.contains("pixel_buffers");
  r["pixel_buffers"] = pixels ? stats["pixel_buffers"] : Json();
  r["images"] = report_images(r, !in.trace->preview.empty(), pixels);
  return r;
}

}  // namespace rtsim::reports
