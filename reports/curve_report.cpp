#include "reports/curve_report.h"

#include <cmath>
#include <map>
#include <vector>

#include <fmt/core.h>

#include "traces/byte_size.h"
#include "traces/text_table.h"

namespace rtsim::reports {

namespace {

const char* cycles_from_name(CurvePoint::Cycles from) {
  switch (from) {
    case CurvePoint::Cycles::Simulated: return "simulated";
    case CurvePoint::Cycles::Interpolated: return "interpolated";
    case CurvePoint::Cycles::Extrapolated: return "extrapolated";
    case CurvePoint::Cycles::Unknown: break;
  }
  return "unknown";
}

// The full model's run at a point, and the curve's error against it.
nlohmann::ordered_json cycle_run_json(const CurvePoint& p, double rays) {
  const CyclePoint& c = p.cycle_run;
  double miss_ratio = c.accesses ? double(c.misses) / double(c.accesses) : 0;
  double dram = double(c.read_bytes + c.writeback_bytes) / rays;
  nlohmann::ordered_json j = {{"cycles", c.cycles},
                              {"accesses", c.accesses},
                              {"misses", c.misses},
                              {"mshr_merges", c.merges},
                              {"miss_ratio", miss_ratio},
                              {"dram_bytes_per_ray", dram},
                              {"read_bytes", c.read_bytes},
                              {"writeback_bytes", c.writeback_bytes},
                              {"cpu_seconds", c.cpu_seconds},
                              {"miss_ratio_error_pp", 100 * (p.miss_ratio - miss_ratio)},
                              {"dram_bytes_error", dram > 0 ? p.dram_bytes / rays / dram - 1 : 0}};
  j["interpolated_cycles"] = p.has_check ? nlohmann::json(p.cycles_check) : nlohmann::json();
  j["interpolation_error"] =
      p.has_check ? nlohmann::json(p.cycles_check / c.cycles - 1) : nlohmann::json();
  return j;
}

std::string percent(const nlohmann::json& v, double scale, const char* format) {
  return v.is_null() ? "-" : fmt::format(fmt::runtime(format), scale * v.get<double>());
}

}  // namespace

std::string size_text(uint64_t bytes, bool compact) {
  if (compact) return byte_size_text(bytes);
  if (bytes % (1 << 20) == 0) return fmt::format("{} MiB", bytes >> 20);
  if (bytes % (1 << 10) == 0) return fmt::format("{} KiB", bytes >> 10);
  return fmt::format("{} B", bytes);
}

nlohmann::ordered_json curve_json(const CacheCurve& curve, const nlohmann::ordered_json& context) {
  double rays = double(std::max<uint64_t>(curve.rays, 1));
  std::map<uint32_t, std::vector<size_t>> by_ways;
  for (size_t i = 0; i < curve.points.size(); ++i) by_ways[curve.points[i].ways].push_back(i);
  nlohmann::ordered_json knees = nlohmann::ordered_json::array(),
                         points = nlohmann::ordered_json::array();
  std::vector<bool> knee(curve.points.size(), false);
  for (const auto& [ways, indices] : by_ways) {
    size_t k = curve_knee(curve, indices);
    knee[k] = true;
    knees.push_back({{"ways", ways}, {"capacity_bytes", curve.points[k].capacity}});
  }
  for (size_t i = 0; i < curve.points.size(); ++i) {
    const CurvePoint& p = curve.points[i];
    nlohmann::ordered_json j = {{"capacity_bytes", p.capacity},
                                {"ways", p.ways},
                                {"sets_per_slice", p.sets_per_slice},
                                {"reads", p.reads},
                                {"misses", p.misses},
                                {"writebacks", p.writebacks},
                                {"miss_ratio", p.miss_ratio},
                                {"miss_ratio_ci95", p.miss_ratio_ci95},
                                {"dram_bytes_per_ray", p.dram_bytes / rays},
                                {"dram_bytes_per_ray_ci95", p.dram_bytes_ci95 / rays},
                                {"knee", bool(knee[i])},
                                {"cycles_from", cycles_from_name(p.cycles_from)}};
    j["cycles"] =
        p.cycles_from == CurvePoint::Cycles::Unknown ? nlohmann::json() : nlohmann::json(p.cycles);
    j["cycle_run"] = p.has_cycle_run ? cycle_run_json(p, rays) : nlohmann::ordered_json();
    points.push_back(j);
  }
  return {{"schema", "rtsim.curve/2"},
          {"context", context},
          {"method", curve.sample_rate > 1
                         ? fmt::format("miniature caches, 1 line in {}", curve.sample_rate)
                         : std::string("exact LRU stack distances per set")},
          {"sample_rate", curve.sample_rate},
          {"pass",
           {{"level", curve.level},
            {"instances", curve.instances},
            {"rays", curve.rays},
            {"reads", curve.reads},
            {"writes", curve.writes},
            {"fills", curve.fills},
            {"block_bytes", curve.block_bytes},
            {"cpu_seconds", curve.cpu_seconds}}},
          {"knees", knees},
          {"points", points}};
}

std::string curve_table(const nlohmann::ordered_json& doc, bool markdown) {
  std::vector<std::vector<std::string>> rows = {
      {doc["pass"]["level"].get<std::string>(), "ways", "miss rate", "below B/ray", "knee",
       "cycles", "cycles from", "full model: miss rate", "DRAM B/ray", "curve error: miss rate",
       "DRAM", "interpolation"}};
  bool sampled = doc["sample_rate"].get<uint32_t>() > 1;
  for (const auto& p : doc["points"]) {
    std::string miss = fmt::format("{:.2f}%", 100 * p["miss_ratio"].get<double>());
    std::string dram = fmt::format("{:.1f}", p["dram_bytes_per_ray"].get<double>());
    if (sampled) {
      miss += fmt::format(" ± {:.2f}", 100 * p["miss_ratio_ci95"].get<double>());
      dram += fmt::format(" ± {:.1f}", p["dram_bytes_per_ray_ci95"].get<double>());
    }
    const auto& run = p["cycle_run"];
    bool ran = !run.is_null();
    rows.push_back({size_text(p["capacity_bytes"].get<uint64_t>()),
                    std::to_string(p["ways"].get<uint32_t>()), miss, dram,
                    p["knee"].get<bool>() ? "knee" : "",
                    p["cycles"].is_null() ? "-" : whole_number(p["cycles"].get<double>()),
                    p["cycles_from"].get<std::string>(),
                    ran ? percent(run["miss_ratio"], 100, "{:.2f}%") : "-",
                    ran ? percent(run["dram_bytes_per_ray"], 1, "{:.1f}") : "-",
                    ran ? percent(run["miss_ratio_error_pp"], 1, "{:+.2f} pp") : "-",
                    ran ? percent(run["dram_bytes_error"], 100, "{:+.2f}%") : "-",
                    ran ? percent(run["interpolation_error"], 100, "{:+.2f}%") : "-"});
  }
  std::vector<size_t> width(rows[0].size(), 0);
  for (const auto& r : rows)
    for (size_t c = 0; c < r.size(); ++c) width[c] = std::max(width[c], r[c].size());
  std::string out;
  for (size_t i = 0; i < rows.size(); ++i) {
    for (size_t c = 0; c < rows[i].size(); ++c)
      out += markdown ? "| " + rows[i][c] + " " : fmt::format("{:<{}}  ", rows[i][c], width[c]);
    out += markdown ? "|\n" : "\n";
    if (markdown && i == 0) {
      for (size_t c = 0; c < rows[i].size(); ++c) out += "|---";
      out += "|\n";
    }
  }
  return out;
}

std::string curve_csv(const nlohmann::ordered_json& doc) {
  std::string out =
      "capacity_bytes,ways,sets_per_slice,reads,misses,writebacks,miss_ratio,miss_ratio_ci95,"
      "dram_bytes_per_ray,dram_bytes_per_ray_ci95,knee,cycles,cycles_from,full_miss_ratio,"
      "full_dram_bytes_per_ray,miss_ratio_error_pp,dram_bytes_error,interpolation_error\n";
  auto number = [](const nlohmann::json& v) {
    return v.is_null() ? std::string() : fmt::format("{:.9g}", v.get<double>());
  };
  for (const auto& p : doc["points"]) {
    const auto& run = p["cycle_run"];
    auto of_run = [&](const char* key) { return run.is_null() ? std::string() : number(run[key]); };
    out += fmt::format(
        "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
        p["capacity_bytes"].get<uint64_t>(), p["ways"].get<uint32_t>(),
        p["sets_per_slice"].get<uint64_t>(), p["reads"].get<uint64_t>(), number(p["misses"]),
        number(p["writebacks"]), number(p["miss_ratio"]), number(p["miss_ratio_ci95"]),
        number(p["dram_bytes_per_ray"]), number(p["dram_bytes_per_ray_ci95"]),
        p["knee"].get<bool>() ? 1 : 0, number(p["cycles"]), p["cycles_from"].get<std::string>(),
        of_run("miss_ratio"), of_run("dram_bytes_per_ray"), of_run("miss_ratio_error_pp"),
        of_run("dram_bytes_error"), of_run("interpolation_error"));
  }
  return out;
}

std::string curve_markdown(const nlohmann::ordered_json& doc) {
  const auto& ctx = doc["context"];
  const auto& pass = doc["pass"];
  std::string out = fmt::format(
      "# {} curve: {} on {}\n\n{} rays; {} block reads, {} writes and {} victim fills of {} "
      "bytes arriving at memory.{} from one functional pass ({:.2f} s CPU); method: {}. "
      "Bytes below: what it sends to the level below (DRAM for the last level).\n\n",
      pass["level"].get<std::string>(), ctx["stream"].get<std::string>(),
      ctx["config"].get<std::string>(), whole_number(pass["rays"].get<uint64_t>()),
      whole_number(pass["reads"].get<uint64_t>()), whole_number(pass["writes"].get<uint64_t>()),
      whole_number(pass["fills"].get<uint64_t>()), pass["block_bytes"].get<uint32_t>(),
      pass["level"].get<std::string>(), pass["cpu_seconds"].get<double>(),
      doc["method"].get<std::string>());
  out += curve_table(doc, true);
  out += "\n![curve](curve.png)\n\nColumns: model/fidelity/CURVE.md.\n";
  return out;
}

std::string curve_family_markdown(const std::vector<nlohmann::ordered_json>& docs) {
  const auto& ctx = docs.front()["context"];
  std::string out = fmt::format(
      "# {1} curves by {0} size: {2} on {3}\n\n{4} rays; one functional pass per {0} size (the "
      "{1}'s references depend on the {0}s); each size's full table in l1-SIZE/curve.md.\n\n"
      "| {0} | {1} | ways | miss rate | below B/ray | knee | cycles | cycles from |\n"
      "|---|---|---|---|---|---|---|---|\n",
      ctx["first_level"].get<std::string>(), ctx["level"].get<std::string>(),
      ctx["stream"].get<std::string>(), ctx["config"].get<std::string>(),
      whole_number(ctx["rays"].get<uint64_t>()));
  for (const auto& doc : docs) {
    uint32_t ways = doc["points"][0]["ways"].get<uint32_t>();
    for (const auto& p : doc["points"]) {
      if (p["ways"].get<uint32_t>() != ways) continue;
      out += fmt::format("| {} | {} | {} | {:.2f}% | {:.1f} | {} | {} | {} |\n",
                         size_text(doc["context"]["first_level_bytes"].get<uint64_t>()),
                         size_text(p["capacity_bytes"].get<uint64_t>()), ways,
                         100 * p["miss_ratio"].get<double>(), p["dram_bytes_per_ray"].get<double>(),
                         p["knee"].get<bool>() ? "knee" : "",
                         p["cycles"].is_null() ? "-" : whole_number(p["cycles"].get<double>()),
                         p["cycles_from"].get<std::string>());
    }
  }
  out += "\n![curves](curve-l1.png)\n\nColumns: model/fidelity/CURVE.md.\n";
  return out;
}

}  // namespace rtsim::reports
