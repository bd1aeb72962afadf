// Bandwidth rooflines of the on-chip ports: each L1's data port, an L2 slice's data port and
// a crossbar link, each the only limit of a run, against its configured bytes a cycle.
#include <fmt/core.h>

#include "model/verify/ray_samples.h"
#include "reports/validate/checks.h"
#include "reports/validate/saturation.h"
#include "workloads/scene.h"

namespace rtsim::validation {
namespace {

constexpr size_t kRoofRays = 2 * kRays;  // N of the port rooflines

// A unit level's counter (mem.NAME.<name>, summed over the units), the mean over the units.
Work level_per_unit(const MemoryLevelConfig& level, const std::string& name) {
  std::string stat = "mem." + level.name + "." + name;
  return [stat](const SimFigures& run) { return run[stat] / run.units(); };
}

struct PortCase {
  const char* id;
  const char* title;
  const char* key;
  double configured;
  Work work;
  const char* how;
  const char* look_at;
};

}  // namespace

std::vector<Check> port_rooflines(const Target& target) {
  const HwConfig& preset = target.config;
  HwConfig base = ceiling_machine(preset, preset.rt.issue_per_cycle);
  base.rt.box.count = base.rt.triangle.count = base.rt.issue_per_cycle = kUnlimited;
  // Reads that miss every level above the last (the L1, and a unit's further levels such as
  // Intel's L1 behind its BVH cache): one set each, and MSHRs for every line a unit can wait for.
  HwConfig missing = base;
  for (size_t i = 0; i + 1 < missing.memory.size(); ++i) {
    MemoryLevelConfig& level = missing.memory[i];
    level.cache.size_bytes = uint64_t(level.cache.line_bytes) * level.cache.ways * level.slices;
    level.cache.mshrs = 512;
  }
  HwConfig l1 = base, l2 = missing, xbar = missing;
  first_level(l1).cache.bytes_per_cycle = first_level(preset).cache.bytes_per_cycle;
  last_level(l2).cache.bytes_per_cycle = last_level(preset).cache.bytes_per_cycle;
  last_level(l2).slices = 1;
  first_level(xbar).link.bytes_per_cycle = first_level(preset).link.bytes_per_cycle;
  std::vector<PortCase> cases = {
      {"roofline.l1_port", "bytes a cycle through each L1's data port", "rt.l1.bytes_per_cycle",
       first_level(preset).cache.bytes_per_cycle, level_per_unit(first_level(preset), "bytes_read"),
       "an L1 that holds the scene; bytes the unit read",
       "Cache::read's data port cursor (model/mem/cache.cpp)"},
      {"roofline.l2_port", "bytes a cycle through an L2 slice's data port", "l2.bytes_per_cycle",
       last_level(preset).cache.bytes_per_cycle,
       stat("mem." + last_level(preset).name + ".bytes_read"),
       "one L2 slice, the levels above it of one set: bytes the L2 served",
       "the L2's data port cursor (model/mem/cache.cpp, SharedLevelsModule)"},
      {"roofline.xbar_link", "bytes a cycle over a unit's crossbar link", "xbar.bytes_per_cycle",
       first_level(preset).link.bytes_per_cycle, level_per_unit(first_level(preset), "bytes_below"),
       "L1s of one set: bytes each L1 received from below",
       "Link and Crossbar (model/mem/crossbar.cpp)"}};
  Scene scene = load_scene("grid:4096");
  // Twice the ceilings' rays: the estimate (the difference of two runs) carries the difference
  // of their first and last stretches, which are not saturated; with 16,000 and 32,000 rays that
  // put the RTX 3080 preset's crossbar link above its configured rate, past the 2% band.
  std::vector<Ray> rays[2] = {sample_diffuse_rays(scene.mesh, kRoofRays, 3),
                              sample_diffuse_rays(scene.mesh, 2 * kRoofRays, 3)};
  BvhImage image = build_bvh_image(scene.mesh, base.bvh);
  std::vector<SimJob> jobs;
  for (const HwConfig* config : {&l1, &l2, &xbar})
    for (const auto& list : rays) jobs.push_back({*config, &image, &list});
  bool any = false;
  for (const PortCase& p : cases) any |= p.configured > 0;
  std::vector<SimFigures> runs = any ? simulate(target, jobs) : std::vector<SimFigures>{};
  std::vector<Check> out;
  for (size_t i = 0; i < cases.size(); ++i) {
    const PortCase& p = cases[i];
    Check c{p.id, "closed_form", p.title};
    c.unit = "bytes per cycle";
    c.source = fmt::format("formula: {} = {}", p.key, p.configured);
    if (p.configured <= 0) {
      c.skipped = std::string(p.key) + " is 0: no limit configured";
      out.push_back(c);
      continue;
    }
    set_band(c, p.configured, 0.02);
    // A run limited elsewhere cannot reach the port: the band's lower side is then a finding.
    c.measured = steady_rate(runs[2 * i], runs[2 * i + 1], p.work);
    c.detail = fmt::format(
        "2 units, {} and {} diffuse rays on grid:4096, every other limit "
        "lifted; {}",
        kRoofRays, 2 * kRoofRays, p.how);
    c.look_at = p.look_at;
    out.push_back(c);
  }
  return out;
}

}  // namespace rtsim::validation
