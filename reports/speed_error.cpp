#include "reports/speed_error.h"

#include <cmath>

#include <fmt/core.h>

#include "reports/page_util.h"
#include "traces/text_table.h"

namespace rtsim::reports {
namespace {

using Json = nlohmann::ordered_json;

constexpr double kGoalCycleError = 0.01;
constexpr double kGoalSpeedup = 20.0;

// value, interval and error against the reference; relative error, or absolute for rates.
Json metric(const Estimate& e, const Estimate& ref, bool rate) {
  if (!e.known || !ref.known) return Json();
  double error = rate ? e.value - ref.value : (ref.value ? e.value / ref.value - 1 : 0.0);
  bool inside = std::abs(e.value - ref.value) <= e.ci95;
  return {{"value", e.value}, {"ci95", e.ci95}, {"error", error}, {"reference_in_ci", inside}};
}

// Over every seed: the root mean square of the error, and how often the interval held the
// reference value.
Json over_seeds(const LevelRun& run, const FidelityResult& f) {
  if (run.other_seeds.empty()) return Json();
  std::vector<const FidelityResult*> all{&run.result};
  for (const FidelityResult& r : run.other_seeds) all.push_back(&r);
  Json out = {{"seeds", all.size()}};
  auto rms = [&](const char* name, Estimate (*m)(const FidelityResult&), bool rate) {
    double squares = 0, covered = 0;
    for (const FidelityResult* r : all) {
      Json x = metric(m(*r), m(f), rate);
      if (x.is_null()) return;
      squares += x["error"].get<double>() * x["error"].get<double>();
      covered += x["reference_in_ci"].get<bool>();
    }
    out[name] = {{"rms_error", std::sqrt(squares / double(all.size()))},
                 {"ci_coverage", covered / double(all.size())}};
  };
  rms(
      "cycles", [](const FidelityResult& r) { return r.cycles; }, false);
  rms(
      "dram_bytes", [](const FidelityResult& r) { return r.dram_bytes; }, false);
  rms(
      "l1_hit_rate", [](const FidelityResult& r) { return r.first_level_hit_rate(); }, true);
  rms(
      "l2_hit_rate", [](const FidelityResult& r) { return r.last_level_hit_rate(); }, true);
  double cpu = 0;
  for (const FidelityResult* r : all) cpu += r->cpu_seconds / double(all.size());
  out["mean_cpu_seconds"] = cpu;
  return out;
}

Json row(const LevelRun& run, const LevelRun& ref) {
  const FidelityResult& r = run.result;
  const FidelityResult& f = ref.result;
  double speedup = r.cpu_seconds > 0 ? f.cpu_seconds / r.cpu_seconds : 0;
  Json out = {
      {"label", run.label},
      {"level", fidelity_level_name(r.level)},
      {"sample_rate", r.sample_rate},
      {"simulated_fraction", double(r.simulated_rays) / double(std::max<uint64_t>(r.rays, 1))},
      {"strata", r.strata},
      {"host_seconds", r.host_seconds},
      {"cpu_seconds", r.cpu_seconds},
      {"speedup", speedup},
      {"cycles", metric(r.cycles, f.cycles, false)},
      {"dram_bytes", metric(r.dram_bytes, f.dram_bytes, false)},
      {"l1_hit_rate", metric(r.first_level_hit_rate(), f.first_level_hit_rate(), true)},
      {"l2_hit_rate", metric(r.last_level_hit_rate(), f.last_level_hit_rate(), true)}};
  bool meets = r.cycles.known &&
               std::abs(out["cycles"]["error"].get<double>()) <= kGoalCycleError &&
               speedup >= kGoalSpeedup;
  out["seeds"] = over_seeds(run, f);
  if (!out["seeds"].is_null()) {
    speedup = f.cpu_seconds / out["seeds"]["mean_cpu_seconds"].get<double>();
    out["speedup"] = speedup;
    meets = speedup >= kGoalSpeedup &&
            out["seeds"]["cycles"]["rms_error"].get<double>() <= kGoalCycleError;
  }
  out["meets_goal"] = meets;
  return out;
}

std::string cell(const Json& m, bool rate) {
  if (m.is_null()) return "-";
  double v = m["value"].get<double>(), ci = m["ci95"].get<double>(), e = m["error"].get<double>();
  std::string value = rate ? fmt::format("{:.2f}%", 100 * v) : fmt::format("{:.4g}", v);
  std::string err = rate ? fmt::format("{:+.2f}pp", 100 * e) : fmt::format("{:+.2f}%", 100 * e);
  if (ci > 0)
    value += rate ? fmt::format(" ±{:.2f}pp", 100 * ci) : fmt::format(" ±{:.2f}%", 100 * ci / v);
  return value + " (" + err + ")";
}

std::string seeds_cell(const Json& s) {
  if (s.is_null()) return "-";
  return fmt::format("{} seeds: cycles {:.2f}%, DRAM {:.2f}%, L1 {:.2f}pp, L2 {:.2f}pp",
                     s["seeds"].get<size_t>(), 100 * s["cycles"]["rms_error"].get<double>(),
                     100 * s["dram_bytes"]["rms_error"].get<double>(),
                     100 * s["l1_hit_rate"]["rms_error"].get<double>(),
                     100 * s["l2_hit_rate"]["rms_error"].get<double>());
}

}  // namespace

Json speed_error_json(const LevelRun& reference, const std::vector<LevelRun>& runs,
                      const Json& context) {
  Json rows = Json::array();
  rows.push_back(row(reference, reference));
  for (const LevelRun& run : runs) rows.push_back(row(run, reference));
  Json results = Json::array();
  for (const LevelRun& run : runs) results.push_back(run.result.to_json());
  Json doc;
  doc["schema"] = kSpeedErrorSchema;
  doc["context"] = context;
  doc["goal"] = {{"max_cycle_error", kGoalCycleError}, {"min_speedup", kGoalSpeedup}};
  doc["reference"] = {{"label", reference.label}, {"result", reference.result.to_json()}};
  doc["rows"] = rows;
  doc["results"] = results;
  return doc;
}

std::string speed_error_table(const Json& doc, bool markdown) {
  const char* head[] = {"level",
                        "CPU s",
                        "speed-up",
                        "simulated",
                        "cycles (error)",
                        "DRAM bytes (error)",
                        "L1 hit rate (error)",
                        "L2 hit rate (error)",
                        "rms error over seeds",
                        "goal"};
  std::vector<std::vector<std::string>> table;
  table.emplace_back(std::begin(head), std::end(head));
  for (const Json& r : doc["rows"]) {
    bool reference = r["label"] == doc["reference"]["label"];
    table.push_back({r["label"].get<std::string>() + (reference ? " (reference)" : ""),
                     fmt::format("{:.2f}", r["cpu_seconds"].get<double>()),
                     fmt::format("{:.1f}x", r["speedup"].get<double>()),
                     fmt::format("{:.1f}%", 100 * r["simulated_fraction"].get<double>()),
                     cell(r["cycles"], false), cell(r["dram_bytes"], false),
                     cell(r["l1_hit_rate"], true), cell(r["l2_hit_rate"], true),
                     seeds_cell(r["seeds"]),
                     reference ? "" : (r["meets_goal"].get<bool>() ? "met" : "-")});
  }
  return text_table(table, markdown);
}

std::string speed_error_markdown(const Json& doc) {
  const Json& c = doc["context"];
  std::string out = fmt::format(
      "# Speed against error: {} on {}\n\n"
      "Stream: {} rays ({}x{}), scene {} ({} triangles). Reference: the full cycle-approximate "
      "model. Times are CPU seconds of each level's run (scene and BVH excluded); with several "
      "seeds, the sampled rows give the first seed's estimate, the mean time and the root mean "
      "square error over all seeds, and the goal is judged on those. Errors are relative (cycles, "
      "DRAM bytes) or in percentage points (hit rates); "
      "± is the sampled level's 95% confidence interval. Goal: cycle error <= {:.0f}% at a "
      "speed-up >= {:.0f}x.\n\n",
      c["workload"].get<std::string>(), c["config"].get<std::string>(),
      whole_number(c["rays"].get<uint64_t>()), c["width"].get<uint32_t>(),
      c["height"].get<uint32_t>(), c["scene"].get<std::string>(),
      whole_number(c["triangles"].get<uint64_t>()),
      100 * doc["goal"]["max_cycle_error"].get<double>(), doc["goal"]["min_speedup"].get<double>());
  return out + speed_error_table(doc, true) + "\n![speed against error](speed_vs_error.png)\n";
}

std::string speed_error_csv(const Json& doc) {
  std::string out =
      "label,level,sample_rate,host_seconds,cpu_seconds,speedup,simulated_fraction,cycles,cycles_"
      "ci95,"
      "cycles_error,dram_bytes,dram_bytes_ci95,dram_bytes_error,l1_hit_rate,l1_hit_rate_ci95,"
      "l1_hit_rate_error,l2_hit_rate,l2_hit_rate_ci95,l2_hit_rate_error,meets_goal\n";
  for (const Json& r : doc["rows"]) {
    out += fmt::format("{},{},{},{:.6f},{:.6f},{:.4f},{:.6f}", r["label"].get<std::string>(),
                       r["level"].get<std::string>(), r["sample_rate"].get<uint32_t>(),
                       r["host_seconds"].get<double>(), r["cpu_seconds"].get<double>(),
                       r["speedup"].get<double>(), r["simulated_fraction"].get<double>());
    for (const char* m : {"cycles", "dram_bytes", "l1_hit_rate", "l2_hit_rate"}) {
      const Json& x = r[m];
      if (x.is_null())
        out += ",,,";
      else
        out += fmt::format(",{:.10g},{:.6g},{:.6g}", x["value"].get<double>(),
                           x["ci95"].get<double>(), x["error"].get<double>());
    }
    out += fmt::format(",{}\n", r["meets_goal"].get<bool>() ? 1 : 0);
  }
  return out;
}

}  // namespace rtsim::reports
