// rtsim verify STREAM: traces every ray of a stream with the model and with Embree, classifies
// each disagreement with the double-precision arbiter, prints a summary, and exits 1 when a
// disagreement is unexplained. The BVH is the built-in config's (that of `rtsim sim` without
// --config), a hardware config's (--config, --set), or given by the BVH options, which are
// shared with `rtsim bench`.
#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "reports/phase_progress.h"
#include "model/bvh/bvh_image.h"
#include "model/bvh/two_level.h"
#include "model/config/hw_config.h"
#include "model/units/traversal.h"
#include "model/verify/verifier.h"
#include "traces/embree_scene.h"
#include "traces/error.h"
#include "traces/stream.h"
#include "workloads/scene.h"

namespace rtsim::app {
namespace {

struct VerifyOptions {
  std::string stream, scene, config;
  std::vector<std::string> sets;
  bool bvh_flags = false;  // a BVH option was given
  bool instances = false;  // two levels (bvh.instancing = "two_level")
  bool flatten = false;    // one level (bvh.instancing = "flatten")
  size_t max_print = 10;
  double t_tolerance = 1e-5;
  BvhConfig bvh;
};

std::string hex(float x) {
  return fmt::format("{:a}", x);
}

std::string hex3(const glm::vec3& v) {
  return fmt::format("({}, {}, {})", hex(v.x), hex(v.y), hex(v.z));
}

std::string answer(const Hit& hit, uint32_t prim) {
  if (!hit.hit()) return "miss";
  if (hit.prim == kAnyPrim) return prim == kNoHit ? "hit" : fmt::format("hit (triangle {})", prim);
  return fmt::format("triangle {} t={} ({:.9g})", hit.prim, hex(hit.t), hit.t);
}

void print_bvh(const BvhImage& image) {
  fmt::print("model      {}\n", describe(image.config));
  fmt::print(
      "bvh        {} nodes x {} B + {} triangles x {} B = {:.2f} MiB; depth {}; "
      "{} treelets ({} oversized)\n",
      image.node_count, image.node_stride, image.triangle_count, image.triangle_stride,
      image.total_bytes() / 1048576.0, image.stats.max_depth, image.treelets.count,
      image.treelets.oversized);
  const TreeletStats& t = image.treelets;
  if (t.count > 0)
    fmt::print(
        "treelets   mean {:.0f} B of nodes + {:.0f} B of leaf triangles; budget {} B counting {}\n",
        double(t.node_bytes) / t.count, double(t.triangle_bytes) / t.count, t.budget_bytes,
        treelet_budget_name(image.config.treelet_budget));
}

void print_two_level(const TwoLevelBvh& bvh, const InstancedMesh& geometry) {
  fmt::print("model      {}, two levels\n", describe(bvh.top.config));
  fmt::print(
      "bvh        top: {} nodes over {} instances; bottom: {} meshes, {} nodes over {} unique "
      "triangles ({} instanced); {:.2f} MiB\n",
      bvh.top.node_count, geometry.instances.size(), bvh.bottom.size(),
      bvh.node_count() - bvh.top.node_count, geometry.unique_triangles(),
      geometry.instanced_triangles(), bvh.total_bytes() / 1048576.0);
}

void print_report(const VerifyReport& r) {
  fmt::print("\n{:<18} {:>10} {:>10} {:>10}\n", "ray type", "rays", "agree", "mismatch");
  for (int t = 0; t < kRayTypeCount; ++t) {
    if (r.rays_by_type[t] == 0) continue;
    fmt::print("{:<18} {:>10} {:>10} {:>10}\n", ray_type_name(RayType(t)), r.rays_by_type[t],
               r.rays_by_type[t] - r.mismatches_by_type[t], r.mismatches_by_type[t]);
  }
  fmt::print("{:<18} {:>10} {:>10} {:>10}\n", "total", r.rays, r.agree, r.mismatches());
  fmt::print("\n{:<18} {:>10} {:>12} {:>12} {:>10}\n", "mismatch class", "count", "model right",
             "embree right", "both");
  for (int c = 0; c < kMismatchClassCount; ++c) {
    const auto& right = r.right[c];
    fmt::print("{:<18} {:>10} {:>12} {:>12} {:>10}\n", mismatch_class_name(MismatchClass(c)),
               r.by_class[c], right[int(RightSide::Model)], right[int(RightSide::Embree)],
               right[int(RightSide::Both)]);
  }
  double n = r.rays ? double(r.rays) : 1.0;
  fmt::print(
      "\nper ray    trav_nodes {:.2f}  trav_leaves {:.2f}  trav_prims {:.2f}  "
      "trav_prim_hits {:.2f}  trav_instances {:.2f}  fetches {:.2f}  bytes {:.1f}\n",
      r.counters.trav_nodes / n, r.counters.trav_leaves / n, r.counters.trav_prims / n,
      r.counters.trav_prim_hits / n, r.counters.trav_instances / n, r.accesses / n,
      r.access_bytes / n);
  fmt::print("hits       model {}  embree {}\n", r.model_hits, r.embree_hits);
}

void print_examples(const std::vector<Mismatch>& examples, const char* what) {
  if (examples.empty()) return;
  fmt::print("\nfirst {} {} rays (hex floats):\n", examples.size(), what);
  for (const Mismatch& m : examples) {
    const Ray& ray = m.ray;
    fmt::print("ray {} {} {}: {} / {}\n", m.index, ray_type_name(ray.type), query_name(ray.query),
               mismatch_class_name(m.verdict.cls), right_side_name(m.verdict.right));
    fmt::print("  org {} dir {} tmin {} tmax {}\n", hex3(ray.org), hex3(ray.dir), hex(ray.tmin),
               hex(ray.tmax));
    fmt::print("  embree {}\n  model  {}\n", answer(m.embree, kNoHit),
               answer(m.model, m.model_prim));
  }
}

// The BVH to check: the options', or with --config/--set the hardware config's.
BvhConfig bvh_to_check(const VerifyOptions& o) {
  if (o.config.empty() && o.sets.empty()) return o.bvh;
  if (o.bvh_flags)
    throw InputError(
        "verify: --config takes the BVH from the hardware config; change it there or with "
        "--set bvh.KEY=VALUE, not with the BVH options");
  return load_hw_config(o.config, o.sets).bvh;
}

int run_verify(const VerifyOptions& o) {
  auto start = std::chrono::steady_clock::now();
  BvhConfig bvh = bvh_to_check(o);
  std::string problem = validate(bvh);
  if (!problem.empty()) throw_input_error("bvh config", "", problem);
  RayStreamReader reader(o.stream);
  const StreamHeader& header = reader.header();
  Scene scene = load_stream_scene(o.stream, header, o.scene);
  fmt::print("stream     {} ({} rays, workload '{}')\n", o.stream, header.total_rays(),
             header.workload);
  fmt::print("scene      {} ({} triangles, fingerprint {:016x})\n", scene.source,
             scene.triangle_count(), scene.fingerprint);
  ArbiterConfig arbiter;
  arbiter.t_tolerance = o.t_tolerance;
  // One level: the flat mesh, both ways. Two: the two-level BVH against Embree's instances,
  // hits judged as flat triangle ids.
  if (o.instances) bvh.instancing = Instancing::TwoLevel;
  if (o.flatten) bvh.instancing = Instancing::Flatten;
  TwoLevelBvh levels = reports::build_scene_bvh(scene, bvh, false);
  if (levels.bottom.empty())
    print_bvh(levels.top);
  else
    print_two_level(levels, scene.instanced);
  TraversalUnit model(levels);
  VerifierSetup checks = make_verifier(model, scene.mesh, scene.instanced, scene.instance_settings,
                                       arbiter, o.max_print);
  Verifier* verifier = checks.verifier.get();
  // Stream the rays in batches: constant memory for any stream length.
  std::vector<Ray> batch;
  while (reader.next_batch(batch, 65536) > 0)
    for (const Ray& ray : batch) verifier->check(ray);
  const VerifyReport& report = verifier->report();
  print_report(report);
  print_examples(report.examples, "mismatching");
  print_examples(report.unexplained_examples, "unexplained");
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (report.unexplained() > 0) {
    fmt::print("\nFAIL: {} unexplained mismatches ({:.1f} s)\n", report.unexplained(), seconds);
    return 1;
  }
  fmt::print("\nOK: {} rays, {} mismatches, all explained ({:.1f} s)\n", report.rays,
             report.mismatches(), seconds);
  return 0;
}

}  // namespace

void add_bvh_options(CLI::App& cmd, BvhConfig& bvh) {
  cmd.add_option("--width", bvh.width, "BVH width: children per node, 2..8")->capture_default_str();
  cmd.add_option_function<std::string>(
         "--format", [&bvh](const std::string& v) { bvh.node_format = *node_format_from_name(v); },
         "Node format")
      ->check(CLI::IsMember(node_format_names()))
      ->default_str(node_format_name(bvh.node_format));
  cmd.add_option_function<std::string>(
         "--triangles",
         [&bvh](const std::string& v) { bvh.triangle_format = *triangle_format_from_name(v); },
         "Triangle layout")
      ->check(CLI::IsMember(triangle_format_names()))
      ->default_str(triangle_format_name(bvh.triangle_format));
  cmd.add_option_function<std::string>(
         "--layout", [&bvh](const std::string& v) { bvh.node_layout = *node_layout_from_name(v); },
         "Node order in memory")
      ->check(CLI::IsMember({"depth-first", "breadth-first", "treelet"}))
      ->default_str(node_layout_name(bvh.node_layout));
  cmd.add_option("--treelet-bytes", bvh.treelet_bytes, "Treelet budget in bytes, 512..65536")
      ->capture_default_str();
  cmd.add_option_function<std::string>(
         "--treelet-budget",
         [&bvh](const std::string& v) { bvh.treelet_budget = *treelet_budget_from_name(v); },
         "What the treelet budget counts")
      ->check(CLI::IsMember({"nodes", "nodes_and_triangles"}))
      ->default_str(treelet_budget_name(bvh.treelet_budget));
  cmd.add_option("--leaf-size", bvh.max_leaf_size,
                 "Most triangles per leaf (cwbvh8: <= 3; amd_box32, amd_box16: 1)")
      ->capture_default_str();
  cmd.add_option("--bins", bvh.sah_bins, "SAH bins per axis: 16 or 32")->capture_default_str();
}

void add_verify_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("verify", "Check every ray of a stream: model against Embree");
  auto options = std::make_shared<VerifyOptions>();
  cmd->add_option("stream", options->stream, "Ray stream (.rays)")->required();
  cmd->add_option("--scene", options->scene, "Scene file or built-in (default: stream header)");
  cmd->add_option("--max-print", options->max_print, "Mismatching rays to print in full")
      ->capture_default_str();
  cmd->add_option("--t-tolerance", options->t_tolerance, "Relative t difference that agrees")
      ->capture_default_str();
  cmd->add_option("--config", options->config,
                  "Verify the BVH this hardware config simulates: " + kConfigForms);
  cmd->add_option("--set", options->sets, "Override a config key: --set bvh.width=4")
      ->allow_extra_args(false);
  cmd->add_flag("--instances", options->instances,
                "Check the two-level BVH (top level over the scene's instances, one bottom level "
                "per unique mesh; a flat scene is one instance) against Embree's instances");
  cmd->add_flag("--flatten", options->flatten,
                "Check one BVH over the world-space triangles, also where the scene places a "
                "mesh more than once")
      ->excludes("--instances");
  add_bvh_options(*cmd, options->bvh);
  cmd->callback([cmd, options, &exit_code] {
    for (const char* flag : {"--width", "--format", "--triangles", "--layout", "--treelet-bytes",
                             "--leaf-size", "--bins"})
      options->bvh_flags |= cmd->count(flag) > 0;
    exit_code = run_verify(*options);
  });
}

}  // namespace rtsim::app
