// Throughput ceilings: the box-test units, the triangle-test units, traversal control's issue
// slots and the dispatcher, each the only limit of a run on a scene that fits the L1, against
// its configured rate; and Little's law between two counters the model keeps apart.
#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "model/verify/ray_samples.h"
#include "reports/validate/checks.h"
#include "reports/validate/saturation.h"
#include "workloads/scene.h"

namespace rtsim::validation {
namespace {

Check ceiling(const char* id, const char* title, double expected, double measured,
              std::string source, std::string look_at) {
  Check c{id, "closed_form", title};
  c.source = std::move(source);
  c.unit = "per cycle per unit";
  set_band(c, expected, 0.02);
  c.measured = measured;
  c.detail = fmt::format(
      "2 units, {} and {} diffuse rays on grid:4096: the difference of work "
      "over the difference of cycles; an L1 that holds the scene, the other "
      "stages set to {} a cycle",
      kRays, 2 * kRays, kUnlimited);
  c.look_at = std::move(look_at);
  return c;
}

}  // namespace

std::vector<Check> throughput_ceilings(const Target& target) {
  const HwConfig& preset = target.config;
  Scene scene = load_scene("grid:4096");
  std::vector<Ray> rays[2] = {sample_diffuse_rays(scene.mesh, kRays, 1),
                              sample_diffuse_rays(scene.mesh, 2 * kRays, 1)};
  // Rays that leave the scene after the root's box test: as short as a ray can be.
  std::vector<Ray> away[2] = {rays[0], rays[1]};
  for (auto& list : away)
    for (Ray& ray : list) {
      ray.org = scene.bounds.hi + glm::vec3(1.0f);
      ray.dir = glm::vec3(1.0f, 0.5f, 0.25f);
    }
  const RtCoreConfig& rt = preset.rt;
  HwConfig box = ceiling_machine(preset, rt.box.count);
  box.rt.triangle.count = box.rt.issue_per_cycle = kUnlimited;
  HwConfig triangle = ceiling_machine(preset, rt.triangle.count);
  triangle.rt.box.count = triangle.rt.issue_per_cycle = kUnlimited;
  HwConfig issue = ceiling_machine(preset, rt.issue_per_cycle);
  issue.rt.box.count = issue.rt.triangle.count = kUnlimited;
  HwConfig dispatch = ceiling_machine(preset, preset.dispatch.rays_per_cycle / 2);
  dispatch.rt.box.count = dispatch.rt.triangle.count = dispatch.rt.issue_per_cycle = kUnlimited;
  BvhImage image = build_bvh_image(scene.mesh, box.bvh);
  std::vector<SimJob> jobs;
  for (const HwConfig* config : {&box, &triangle, &issue, &dispatch})
    for (int i = 0; i < 2; ++i)
      jobs.push_back({*config, &image, config == &dispatch ? &away[i] : &rays[i]});
  std::vector<SimFigures> runs = simulate(target, jobs);
  std::vector<Check> out;
  out.push_back(ceiling(
      "ceiling.box_tests", "box-test issues a cycle, the box units saturated", rt.box.count,
      steady_rate(runs[0], runs[1], per_unit("box.issues")),
      fmt::format("formula: rt.box.count {} pipelined units, one issue ({} boxes) a cycle each",
                  rt.box.count, rt.box.issue_width),
      "TestUnitPool::reserve (model/sched/test_unit_pool.cpp)"));
  out.push_back(ceiling(
      "ceiling.triangle_tests", "triangle-test issues a cycle, the triangle units saturated",
      rt.triangle.count, steady_rate(runs[2], runs[3], per_unit("triangle.issues")),
      fmt::format("formula: rt.triangle.count {} pipelined units, one issue ({} triangles) a "
                  "cycle each",
                  rt.triangle.count, rt.triangle.issue_width),
      "TestUnitPool::reserve (model/sched/test_unit_pool.cpp)"));
  out.push_back(ceiling("ceiling.issue_slots", "traversal steps started a cycle, control saturated",
                        rt.issue_per_cycle,
                        steady_rate(runs[4], runs[5], per_unit("control.issues")),
                        fmt::format("formula: rt.issue_per_cycle {}", rt.issue_per_cycle),
                        "RtCore::claim_issue (model/sched/rt_core.cpp)"));
  Check d =
      ceiling("ceiling.dispatch", "rays handed out a cycle, the dispatcher saturated",
              preset.dispatch.rays_per_cycle, steady_rate(runs[6], runs[7], stat("rays")),
              fmt::format("formula: dispatch.rays_per_cycle {}", preset.dispatch.rays_per_cycle),
              "RayDispatcher::take (model/sched/dispatcher.cpp)");
  d.unit = "rays per cycle (all units)";
  d.detail = fmt::format(
      "2 units, {} and {} rays that leave the scene after the root's box "
      "test: the difference of rays over the difference of cycles; every "
      "other stage set to {} a cycle",
      kRays, 2 * kRays, kUnlimited);
  out.push_back(d);
  return out;
}

Check littles_law(const Target& target) {
  const HwConfig& preset = target.config;
  Check c{"little.rays_in_flight", "closed_form",
          "rays in flight = throughput x mean latency, from two independent counters"};
  c.source =
      "formula: Little's law, L = lambda W (L: the units' integral of occupied ray slots "
      "over cycles; lambda: rays / cycles; W: the per-ray latency the stats collector "
      "keeps from dispatch to retirement)";
  c.unit = "rays";
  if (preset.rt.mode == TraversalMode::Treelet) {
    c.skipped = "treelet mode: a postponed ray waits in the queues, outside any ray slot";
    return c;
  }
  Scene scene = load_scene("grid:4096");
  HwConfig config = preset;
  config.dispatch.rays_per_cycle = 1 << 20;  // a ray's slot is taken in its dispatch cycle
  BvhImage image = build_bvh_image(scene.mesh, config.bvh);
  std::vector<Ray> rays = sample_diffuse_rays(scene.mesh, kRays, 2);
  SimFigures run = simulate(target, {{config, &image, &rays}})[0];
  double cycles = run["cycles"];
  set_band(c, run["rays"] / cycles * run.latency_mean(), 0.005);
  c.measured = run["rt.ray_slot_cycles"] / cycles;
  c.detail = fmt::format(
      "the config as given, {} diffuse rays on grid:4096, dispatch unlimited "
      "so that a ray's latency starts when it takes its slot",
      kRays);
  c.look_at = "RtCore::account (slot integral) and SimStatsCollector::retired (latency)";
  return c;
}

}  // namespace rtsim::validation
