#include "model/fidelity/fidelity_result.h"

#include "traces/host_clock.h"

namespace rtsim {
namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kLevelNames[] = {"functional", "cache", "cycle", "sampled"};

double ratio(double num, double den) {
  return den > 0 ? num / den : 0.0;
}

Json estimate_json(const Estimate& e) {
  if (!e.known) return Json();
  return Json{{"value", e.value}, {"ci95", e.ci95}};
}

Estimate estimate_from(const nlohmann::json& j) {
  if (j.is_null()) return {};
  return {true, j.at("value").get<double>(), j.at("ci95").get<double>()};
}

Json levels_json(const LevelEstimates& levels) {
  Json out = Json::array();
  for (const LevelEstimate& l : levels)
    out.push_back({{"name", l.name}, {"hit_rate", estimate_json(l.hit_rate)}});
  return out;
}

LevelEstimates levels_from(const nlohmann::json& j) {
  LevelEstimates out;
  for (const auto& l : j)
    out.push_back({l.at("name").get<std::string>(), estimate_from(l.at("hit_rate"))});
  return out;
}

LevelEstimates exact_levels(const ReadCounts& reads, const std::vector<std::string>& names) {
  LevelEstimates out;
  for (size_t i = 0; i < names.size(); ++i)
    out.push_back(
        {names[i], Estimate::exact(ratio(double(reads.hits[i]), double(reads.accesses[i])))});
  return out;
}

}  // namespace

HostTimer::HostTimer() : wall_(wall_seconds()), cpu_(rtsim::cpu_seconds()) {}

void HostTimer::stop(FidelityResult& result) const {
  result.host_seconds = wall_seconds() - wall_;
  result.cpu_seconds = rtsim::cpu_seconds() - cpu_;
}

const char* fidelity_level_name(FidelityLevel level) {
  return kLevelNames[int(level)];
}

std::optional<FidelityLevel> fidelity_level_from_name(const std::string& name) {
  for (int i = 0; i < 4; ++i)
    if (name == kLevelNames[i]) return FidelityLevel(i);
  return std::nullopt;
}

CostTotals& CostTotals::operator+=(const CostTotals& o) {
  rays += o.rays;
  nodes += o.nodes;
  triangles += o.triangles;
  reads += o.reads;
  latency += o.latency;
  return *this;
}

Estimate first_level_hit_rate(const LevelEstimates& levels) {
  return levels.empty() ? Estimate{} : levels.front().hit_rate;
}

Estimate last_level_hit_rate(const LevelEstimates& levels) {
  return levels.empty() ? Estimate{} : levels.back().hit_rate;
}

double FidelityResult::mrays_per_second() const {
  return cycles.known ? ratio(double(rays), cycles.value) * clock_ghz * 1e3 : 0.0;
}

void set_exact_estimates(FidelityResult& result,
                         const std::array<CostTotals, kRayTypeCount>& by_type,
                         const std::vector<std::string>& levels, bool timed) {
  bool cached = !levels.empty();
  CostTotals all;
  for (int t = 0; t < kRayTypeCount; ++t) {
    const CostTotals& c = by_type[t];
    all += c;
    TypeEstimate& e = result.types[t];
    e.rays = c.rays;
    if (c.rays == 0) continue;
    double n = double(c.rays);
    e.nodes_per_ray = Estimate::exact(c.nodes / n);
    e.triangles_per_ray = Estimate::exact(c.triangles / n);
    if (cached) {
      e.levels = exact_levels(c.reads, levels);
      e.dram_bytes_per_ray = Estimate::exact(c.reads.dram_bytes / n);
    }
    if (timed) e.latency_mean = Estimate::exact(c.latency / n);
  }
  result.rays = result.measured_rays = all.rays;
  double n = double(std::max<uint64_t>(all.rays, 1));
  result.nodes_per_ray = Estimate::exact(all.nodes / n);
  result.triangles_per_ray = Estimate::exact(all.triangles / n);
  if (cached) {
    result.levels = exact_levels(all.reads, levels);
    result.dram_bytes = Estimate::exact(double(all.reads.dram_bytes));
  }
}

Json FidelityResult::to_json() const {
  Json types_json = Json::object();
  for (int t = 0; t < kRayTypeCount; ++t) {
    const TypeEstimate& e = types[t];
    if (e.rays == 0) continue;
    types_json[ray_type_name(RayType(t))] = {
        {"rays", e.rays},
        {"nodes_per_ray", estimate_json(e.nodes_per_ray)},
        {"triangles_per_ray", estimate_json(e.triangles_per_ray)},
        {"levels", levels_json(e.levels)},
        {"dram_bytes_per_ray", estimate_json(e.dram_bytes_per_ray)},
        {"latency_mean", estimate_json(e.latency_mean)}};
  }
  return {{"level", fidelity_level_name(level)},
          {"sample_rate", sample_rate},
          {"sample_method", sample_method},
          {"rays", rays},
          {"simulated_rays", simulated_rays},
          {"measured_rays", measured_rays},
          {"strata", strata},
          {"clock_ghz", clock_ghz},
          {"time_model", time_model},
          {"caveat", caveat.empty() ? Json() : Json(caveat)},
          {"cycles", estimate_json(cycles)},
          {"mrays_per_second", cycles.known ? Json(mrays_per_second()) : Json()},
          {"dram_bytes", estimate_json(dram_bytes)},
          {"levels", levels_json(levels)},
          {"nodes_per_ray", estimate_json(nodes_per_ray)},
          {"triangles_per_ray", estimate_json(triangles_per_ray)},
          {"ray_types", types_json},
          {"host_seconds", host_seconds},
          {"cpu_seconds", cpu_seconds}};
}

FidelityResult FidelityResult::from_json(const nlohmann::json& doc) {
  FidelityResult r;
  r.level = fidelity_level_from_name(doc.at("level").get<std::string>()).value();
  r.sample_rate = doc.at("sample_rate").get<uint32_t>();
  r.sample_method = doc.at("sample_method").get<std::string>();
  r.rays = doc.at("rays").get<uint64_t>();
  r.simulated_rays = doc.at("simulated_rays").get<uint64_t>();
  r.measured_rays = doc.at("measured_rays").get<uint64_t>();
  r.strata = doc.at("strata").get<uint32_t>();
  r.clock_ghz = doc.at("clock_ghz").get<double>();
  r.time_model = doc.at("time_model").get<std::string>();
  if (doc.contains("caveat") && doc["caveat"].is_string())
    r.caveat = doc["caveat"].get<std::string>();
  r.cycles = estimate_from(doc.at("cycles"));
  r.dram_bytes = estimate_from(doc.at("dram_bytes"));
  r.levels = levels_from(doc.at("levels"));
  r.nodes_per_ray = estimate_from(doc.at("nodes_per_ray"));
  r.triangles_per_ray = estimate_from(doc.at("triangles_per_ray"));
  for (const auto& [name, t] : doc.at("ray_types").items()) {
    auto type = ray_type_from_name(name);
    if (!type) continue;
    TypeEstimate& e = r.types[int(*type)];
    e.rays = t.at("rays").get<uint64_t>();
    e.nodes_per_ray = estimate_from(t.at("nodes_per_ray"));
    e.triangles_per_ray = estimate_from(t.at("triangles_per_ray"));
    e.levels = levels_from(t.at("levels"));
    e.dram_bytes_per_ray = estimate_from(t.at("dram_bytes_per_ray"));
    e.latency_mean = estimate_from(t.at("latency_mean"));
  }
  r.host_seconds = doc.at("host_seconds").get<double>();
  r.cpu_seconds = doc.at("cpu_seconds").get<double>();
  return r;
}

}  // namespace rtsim
