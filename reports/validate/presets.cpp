// The config under test against its vendor's published ray rate (model/VALIDATION.md,
// "Presets"): primary rays of single meshes at 1080p, rays per cycle per RT unit at the config's
// own clock, within the band the source supports.
#include <filesystem>
#include <map>

#include <fmt/core.h>

#include "model/verify/ray_samples.h"
#include "reports/validate/checks.h"
#include "traces/embree_scene.h"
#include "workloads/scene.h"

namespace rtsim::validation {
namespace {

// A rays/s figure a vendor published for a part, and what it covers.
struct VendorFigure {
  const char* config;  // the config `name` it applies to
  const char* source;
  double rays_per_second;
  uint32_t rt_units;  // of the part it was measured on
};

const VendorFigure kFigures[] = {
    {"rtx2080ti",
     "NVIDIA Turing launch (AnandTech's Turing deep dive): RTX 2080 Ti, 68 RT cores, \"10 Giga "
     "Rays/s\", primary rays on single-mesh scenes whose framing NVIDIA did not publish",
     10e9, 68}};

// The figure's framing is unpublished, so the check assumes the mesh covers kCoverage of the
// frame and reports the rate at the bracket's ends beside it; the band is what a +-20% reading of
// a single headline figure allows, no wider.
constexpr double kCoverage = 0.6;
constexpr double kBracket[2] = {0.4, 0.8};
constexpr double kTolerance = 0.2;

// The share of a width x height frame's rays from `distance` that hit the mesh (Embree).
double coverage(const Scene& scene, const EmbreeScene& embree, float distance) {
  std::vector<Ray> probe = sample_camera_rays(scene.mesh, 192, 108, distance);
  size_t hits = 0;
  for (const Ray& ray : probe) hits += embree.intersect(ray).hit();
  return double(hits) / double(probe.size());
}

// The camera distance at which the mesh covers `share` of the frame: bisection on the distance
// (coverage falls as the camera backs off), from just outside the bounding sphere.
float distance_for(const Scene& scene, const EmbreeScene& embree, double share) {
  float near = 0.95f, far = 8.0f;
  for (int i = 0; i < 24; ++i) {
    float mid = 0.5f * (near + far);
    (coverage(scene, embree, mid) > share ? near : far) = mid;
  }
  return 0.5f * (near + far);
}

// Every resource's utilisation (mean over units and instances) and where memory reads waited.
std::string resource_line(const HwConfig& c, const SimFigures& run) {
  double units = c.rt_units, rays = run["rays"];
  std::string line = fmt::format(
      "busy: dispatch {:.0f}%, issue {:.0f}%, box units {:.0f}%, triangle units {:.0f}%, ray "
      "slots {:.0f}%",
      100 * run["dispatch.utilisation"], 100 * run.units_sum("control.utilisation") / units,
      100 * run.units_sum("box.utilisation") / units,
      100 * run.units_sum("triangle.utilisation") / units, 100 * run["rt.slot_occupancy"]);
  for (const MemoryLevelConfig& level : c.memory) {
    std::string m = "mem." + level.name + ".";
    line += fmt::format(
        "; {} port {:.0f}% (cycles a ray waiting for: ports {:.1f}, banks {:.1f}, MSHRs {:.1f})",
        level.name, 100 * run[m + "port_utilisation"], run[m + "port_stall_cycles"] / rays,
        run[m + "bank_stall_cycles"] / rays, run[m + "mshr_stall_cycles"] / rays);
  }
  return line + fmt::format("; DRAM {:.0f}%", 100 * run["dram.utilisation"]);
}

}  // namespace

std::vector<Check> preset_checks(const Target& target,
                                 const std::function<void(const std::string&)>& progress) {
  const HwConfig& config = target.config;
  const VendorFigure* figure = nullptr;
  for (const VendorFigure& f : kFigures)
    if (config.name == f.config) figure = &f;
  std::vector<Check> out;
  for (const char* mesh : {"bunny", "dragon"}) {
    Check c{fmt::format("vendor.{}.{}", config.name, mesh), "presets",
            fmt::format("{}, 1920x1080 primary rays of the {} covering {:.0f}% of the frame: rays "
                        "a cycle per RT unit",
                        config.name, mesh, 100 * kCoverage)};
    c.unit = "rays per cycle per unit";
    std::string scene_path = shared_scene_path(mesh);
    if (!figure) {
      c.skipped =
          "no published rays/s for this config (one exists for rtx2080ti; the other vendors "
          "publish test rates, which the ceiling checks hold)";
      out.push_back(c);
      continue;
    }
    c.source = figure->source;
    if (!std::filesystem::exists(scene_path)) {
      c.skipped = scene_path + " not found";
      out.push_back(c);
      continue;
    }
    progress(fmt::format("presets: {} on the {}", config.name, mesh));
    set_band(c, figure->rays_per_second / (figure->rt_units * config.clock_ghz * 1e9), kTolerance);
    Scene scene = load_scene(scene_path);
    EmbreeScene embree(scene.mesh);
    BvhImage image = build_bvh_image(scene.mesh, config.bvh);
    std::vector<double> shares = {kCoverage, kBracket[0], kBracket[1]};
    std::vector<std::vector<Ray>> rays;
    for (double share : shares)
      rays.push_back(
          sample_camera_rays(scene.mesh, 1920, 1080, distance_for(scene, embree, share)));
    std::vector<SimJob> jobs;
    for (const std::vector<Ray>& r : rays) jobs.push_back({config, &image, &r});
    std::vector<SimFigures> runs = simulate(target, jobs);
    auto rate = [&](const SimFigures& run) { return run["rays_per_cycle"] / config.rt_units; };
    c.measured = rate(runs[0]);
    c.detail = fmt::format(
        "the config under test at its {} GHz; {:.2f} nodes a ray; at {:.0f}% and {:.0f}% "
        "coverage {:.4f} and {:.4f}; {}; the band is +-{:.0f}% of {:g} rays/s / ({} RT units x "
        "{} GHz). {}",
        config.clock_ghz, runs[0]["type.camera.nodes_per_ray"], 100 * kBracket[0],
        100 * kBracket[1], rate(runs[1]), rate(runs[2]), resource_line(config, runs[0]),
        100 * kTolerance, figure->rays_per_second, figure->rt_units, config.clock_ghz,
        "Left out of the model, so of this rate: ray generation and hit shading in the SMs, the "
        "trace call's round trip, and their traffic in the L2 and DRAM.");
    c.look_at =
        "the busiest resource above; the unit counts, test rates and latencies against the "
        "vendor's part (configs/SOURCES.md)";
    out.push_back(c);
  }
  return out;
}

}  // namespace rtsim::validation
