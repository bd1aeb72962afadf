// Sensitivity: for each cost the model leaves out or simplifies, a bracketing run on Conference
// says how far the headline figures (cycles, DRAM bytes a ray, L2 hit rate) move. These are
// reported, not judged, except exact event order, which the model claims to approximate.
#include <cmath>
#include <filesystem>

#include <fmt/core.h>

#include "model/verify/ray_samples.h"
#include "reports/validate/checks.h"
#include "workloads/scene.h"

namespace rtsim::validation {
namespace {

constexpr size_t kRays = 32768;

struct Bracket {
  const char* id;
  const char* title;
  const char* how;
  std::function<void(HwConfig&)> change;
};

std::vector<Bracket> brackets(const HwConfig& preset) {
  bool banked = preset.dram_model == DramModel::Banked;
  return {
      {"sensitivity.dram_detail", "the DRAM's detail: the other DRAM model",
       banked ? "dram.model = simple with the banked DRAM's peak bandwidth and unloaded "
                "closed-row latency: one bus, no banks, rows or refresh"
              : "dram.model = banked: channels, banks, rows and refresh",
       [banked](HwConfig& c) {
         if (banked) c.dram = dram_for_analysis(c);  // the same peak and unloaded latency
         c.dram_model = banked ? DramModel::Simple : DramModel::Banked;
       }},
      {"sensitivity.spills", "stack spills: a stack deep enough never to spill",
       "rt.stack.entries = 64", [](HwConfig& c) { c.rt.stack.entries = 64; }},
      {"sensitivity.competing_traffic",
       "competing traffic (shading, textures, other clients), left out: half the L2 and half "
       "the DRAM bandwidth",
       "l2.size_bytes / 2 and dram.channels / 2 (simple DRAM: dram.bytes_per_cycle / 2)",
       [](HwConfig& c) {
         last_level(c).cache.size_bytes /= 2;
         c.banked_dram.channels = std::max(1u, c.banked_dram.channels / 2);
         c.dram.bytes_per_cycle /= 2;
       }},
      {"sensitivity.shading", "shading, left out: a 200-cycle trace-call round trip per ray",
       "rt.setup_latency + 200 (ray generation before the trace, hit shading after it)",
       [](HwConfig& c) { c.rt.setup_latency += 200; }},
      {"sensitivity.exact_order", "temporal decoupling: exact global event order",
       "sim.quantum_cycles = 1", [](HwConfig& c) { c.sim.quantum_cycles = 1; }},
  };
}

}  // namespace

std::vector<Check> sensitivity_checks(const Target& target) {
  const HwConfig& preset = target.config;
  std::vector<Bracket> cases = brackets(preset);
  std::string scene_path = shared_scene_path("conference");
  std::vector<Check> out;
  for (const Bracket& b : cases) {
    Check c{b.id, "sensitivity", b.title};
    c.unit = "change in cycles";
    c.source = "bracketing run: " + std::string(b.how);
    out.push_back(c);
  }
  if (!std::filesystem::exists(scene_path)) {
    for (Check& c : out) c.skipped = scene_path + " not found";
    return out;
  }
  Scene scene = load_scene(scene_path);
  std::vector<Ray> rays = sample_diffuse_rays(scene.mesh, kRays, 11);
  BvhImage image = build_bvh_image(scene.mesh, preset.bvh);
  std::vector<SimJob> jobs{{preset, &image, &rays}};
  std::vector<HwConfig> configs(cases.size(), preset);
  for (size_t i = 0; i < cases.size(); ++i) cases[i].change(configs[i]);
  for (const HwConfig& config : configs) jobs.push_back({config, &image, &rays});
  std::vector<SimFigures> runs = simulate(target, jobs);
  const SimFigures& base = runs[0];
  const std::string last_hit_rate = "mem." + last_level(preset).name + ".hit_rate";
  for (size_t i = 0; i < cases.size(); ++i) {
    const SimFigures& run = runs[i + 1];
    Check& c = out[i];
    c.measured = run["cycles"] / base["cycles"] - 1;
    c.detail = fmt::format(
        "{} diffuse rays on Conference, the config as given against the bracket: cycles {:.0f} "
        "-> {:.0f}, DRAM bytes a ray {:.1f} -> {:.1f}, L2 hit rate {:.1f}% -> {:.1f}%",
        kRays, base["cycles"], run["cycles"], base["dram.bytes_per_ray"], run["dram.bytes_per_ray"],
        100 * base[last_hit_rate], 100 * run[last_hit_rate]);
    c.look_at = "the stats of both runs (rtsim sim --set ...)";
  }
  Check& exact = out.back();
  exact.expected = 0;
  exact.lo = -0.02;
  exact.hi = 0.02;
  exact.source += "; pass: within 2% of exact order (model/SIM.md, temporal decoupling)";
  exact.look_at = "late data (rtK.late_data) and requests served out of order (model/SIM.md)";
  return out;
}

}  // namespace rtsim::validation
