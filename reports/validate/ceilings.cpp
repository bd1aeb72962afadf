// Throughput ceilings: the box-test units, the triangle-test units, traversal control's issue
// slots and the dispatcher, each the only limit of a run on a scene that fits the L1, against
// its configured rate; and Little's law between two counters the model keeps apart.
#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "model/verify/ray_samples.h"
#include "reports/validate/checks.h"
#include "model/bvh/intel_nodes.h"
#include "model/bvh/wide_bvh.h"
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

// A mesh of `copies` copies of one triangle in the plane z = 0: the BVH is one leaf of them.
TriangleMesh stacked_triangles(uint32_t copies) {
  TriangleMesh mesh;
  mesh.positions = {{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};
  mesh.triangles.assign(copies, {0u, 1u, 2u});
  return mesh;
}

// The most children a node of the format holds, and the most triangles its leaf holds
// (model/bvh/bvh_config.cpp validate: cwbvh8 3, xe6 a quad's 2, amd formats one triangle node).
uint32_t node_slots(NodeFormat format) {
  if (format == NodeFormat::Xe6) return kXeNodeSlots;
  return is_amd_format(format) ? 4 : kMaxWidth;
}

uint32_t leaf_triangles(NodeFormat format) {
  switch (format) {
    case NodeFormat::Cwbvh8: return 3;
    case NodeFormat::Xe6: return 2;
    case NodeFormat::AmdBox32:
    case NodeFormat::AmdBox16: return 1;
    default: return 254;
  }
}

// The largest multiple of `width` at most `most` (at least `width` when most < width).
uint32_t whole_issues(uint32_t width, uint32_t most) {
  return std::max(width, most / width * width);
}

}  // namespace

std::vector<Check> throughput_ceilings(const Target& target) {
  const HwConfig& preset = target.config;
  const RtCoreConfig& rt = preset.rt;
  bool shared = rt.test_issue == TestIssue::Shared;
  Scene scene = load_scene("grid:4096");
  std::vector<Ray> rays[2] = {sample_diffuse_rays(scene.mesh, kRays, 1),
                              sample_diffuse_rays(scene.mesh, 2 * kRays, 1)};
  // Rays that leave the scene after the root's box test: as short as a ray can be.
  std::vector<Ray> away[2] = {rays[0], rays[1]}, down[2] = {rays[0], rays[1]};
  for (auto& list : away)
    for (Ray& ray : list) {
      ray.org = scene.bounds.hi + glm::vec3(1.0f);
      ray.dir = glm::vec3(1.0f, 0.5f, 0.25f);
    }
  // Rays straight down onto the stacked triangles: a root step, then the whole leaf.
  for (auto& list : down)
    for (size_t i = 0; i < list.size(); ++i) {
      list[i].org =
          glm::vec3(0.1f + 0.3f * float(i % 97) / 97, 0.1f + 0.3f * float(i % 89) / 89, 1.0f);
      list[i].dir = glm::vec3(0.0f, 0.0f, -1.0f);
      list[i].tmin = 0.0f;
      list[i].tmax = 2.0f;
    }
  // Box tests: the root's box test fills whole issues when the node is a multiple of the
  // width wide (a BVH6 for 6 boxes an issue); wider issues than a node test a node each.
  uint32_t widest = node_slots(preset.bvh.node_format);
  uint32_t box_width = std::min(rt.box.issue_width, widest);
  HwConfig box = ceiling_machine(preset, rt.box.count);
  box.rt.triangle.count = shared ? rt.box.count : kUnlimited;
  box.rt.issue_per_cycle = kUnlimited;
  box.dispatch.rays_per_cycle = 4 * kUnlimited;
  box.bvh.width = int(whole_issues(box_width, widest));
  // Triangle tests: a leaf of whole issues of triangles (as many as the format's leaf holds).
  // Ray slots for the rate the leaf allows (2 steps a ray), so that bookings stay within the
  // units' calendar.
  uint32_t width = rt.triangle.issue_width;
  uint32_t most_leaf = std::min(leaf_triangles(preset.bvh.node_format), 4 * width);
  uint32_t leaf = std::min(whole_issues(width, most_leaf), most_leaf);
  double issues_per_ray = std::ceil(double(leaf) / width) + (shared ? 1 : 0);
  HwConfig triangle = ceiling_machine(preset, 2.0 * rt.triangle.count / issues_per_ray);
  triangle.rt.box.count = shared ? rt.triangle.count : kUnlimited;
  triangle.rt.issue_per_cycle = kUnlimited;
  triangle.bvh.max_leaf_size = int(leaf);
  HwConfig issue = ceiling_machine(preset, rt.issue_per_cycle);
  issue.rt.box.count = issue.rt.triangle.count = kUnlimited;
  HwConfig dispatch = ceiling_machine(preset, preset.dispatch.rays_per_cycle / 2);
  dispatch.rt.box.count = dispatch.rt.triangle.count = dispatch.rt.issue_per_cycle = kUnlimited;
  BvhImage image = build_bvh_image(scene.mesh, issue.bvh);
  BvhImage box_image = build_bvh_image(scene.mesh, box.bvh);
  BvhImage leaf_image = build_bvh_image(stacked_triangles(leaf), triangle.bvh);
  std::vector<SimJob> jobs;
  for (int i = 0; i < 2; ++i) jobs.push_back({box, &box_image, &away[i]});
  for (int i = 0; i < 2; ++i) jobs.push_back({triangle, &leaf_image, &down[i]});
  for (const HwConfig* config : {&issue, &dispatch})
    for (int i = 0; i < 2; ++i)
      jobs.push_back({*config, &image, config == &dispatch ? &away[i] : &rays[i]});
  std::vector<SimFigures> runs = simulate(target, jobs);
  // Shared units: triangle tests a cycle of the issue slots the root's box tests left.
  Work triangle_tests = per_unit("triangle.tests");
  double box_issue_cycles =
      shared ? steady_rate(runs[2], runs[3], per_unit("box.issues")) / rt.triangle.count : 0.0;
  std::vector<Check> out;
  out.push_back(ceiling(
      "ceiling.box_tests", "box tests a cycle, the box units saturated", rt.box.count * box_width,
      steady_rate(runs[0], runs[1], per_unit("box.tests")),
      fmt::format(
          "formula: rt.box.count {} pipelined units x rt.box.issue_width {} boxes an "
          "issue{}, one issue a cycle each{}",
          rt.box.count, rt.box.issue_width,
          box_width < rt.box.issue_width ? fmt::format(" (at most a node's {})", widest) : "",
          shared ? ", shared with the triangle tests" : ""),
      "TestUnitPool::reserve_as (model/sched/test_unit_pool.cpp)"));
  out.back().detail = fmt::format(
      "2 units, {} and {} rays that leave grid:4096 after the root's box test, on a BVH{} "
      "(whole issues): the difference of tests over the difference of cycles; an L1 that "
      "holds the scene, the other stages set to {} a cycle",
      kRays, 2 * kRays, box.bvh.width, kUnlimited);
  out.push_back(ceiling(
      "ceiling.triangle_tests", "triangle tests a cycle, the triangle units saturated",
      rt.triangle.count * std::min(width, leaf),
      steady_rate(runs[2], runs[3], triangle_tests) / (1.0 - box_issue_cycles),
      fmt::format("formula: rt.triangle.count {} pipelined units x rt.triangle.issue_width {} "
                  "triangles an issue{}, one issue a cycle each{}",
                  rt.triangle.count, width,
                  leaf < width ? fmt::format(" (at most a leaf's {})", leaf) : "",
                  shared ? " (shared: over the cycles the root's box issues leave)" : ""),
      "TestUnitPool::reserve_as (model/sched/test_unit_pool.cpp)"));
  out.back().detail = fmt::format(
      "2 units, {} and {} rays onto a leaf of {} stacked triangles: the difference of tests "
      "over the difference of cycles; an L1 that holds the scene, the other stages set to {} "
      "a cycle",
      kRays, 2 * kRays, leaf, kUnlimited);
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
