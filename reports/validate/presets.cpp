// GPU-like presets against their vendors' ray rates (model/VALIDATION.md, "Presets"): primary
// rays of one mesh at 1080p, rays per cycle per RT unit, within 2x of the published figure.
#include <filesystem>

#include <fmt/core.h>

#include "model/verify/ray_samples.h"
#include "reports/validate/checks.h"
#include "workloads/scene.h"

namespace rtsim::validation {
namespace {

struct VendorFigure {
  const char* preset;
  const char* source;
  double rays_per_second;  // 0: none published
  double boost_mhz;
  uint32_t rt_cores;
};

const VendorFigure kFigures[] = {
    {"rtx2080ti",
     "NVIDIA Turing launch (AnandTech's Turing deep dive): RTX 2080 Ti, 68 RT cores at a "
     "1545 MHz boost, \"10 Giga Rays/s\" (workload undisclosed)",
     10e9, 1545, 68},
    {"rtx3080", "NVIDIA publishes no rays/s for Ampere (only \"2x Turing's ray-triangle rate\")", 0,
     0, 0},
    {"rtx4090", "NVIDIA publishes no rays/s for Ada (only \"2x Ampere's ray-triangle rate\")", 0, 0,
     0},
    {"rdna2", "AMD publishes box and triangle tests per clock for RDNA 2, no rays/s", 0, 0, 0},
    {"rdna3", "AMD publishes box and triangle tests per clock for RDNA 3, no rays/s", 0, 0, 0},
    {"rdna4", "AMD publishes box and triangle tests per clock for RDNA 4, no rays/s", 0, 0, 0},
    {"xe-hpg", "Intel publishes box and triangle tests per clock for Xe-HPG, no rays/s", 0, 0, 0},
    {"xe2", "Intel publishes box and triangle tests per clock for Xe2, no rays/s", 0, 0, 0},
};

// What the RT units of the model leave out, which a vendor's rate includes or hides.
constexpr const char* kMissingCosts =
    "Left out of the model, so of this rate: ray generation and hit shading in the SMs, the "
    "trace call's round trip, and their traffic in the L2 and DRAM; the vendor's workload is "
    "not disclosed.";

}  // namespace

std::vector<Check> preset_checks(const Target& target,
                                 const std::function<void(const std::string&)>& progress) {
  std::vector<Check> out;
  for (const VendorFigure& f : kFigures) {
    for (const char* mesh : {"bunny", "dragon"}) {
      Check c{fmt::format("vendor.{}.{}", f.preset, mesh), "presets",
              fmt::format("{} preset, 1920x1080 primary rays of the {}: rays a cycle per RT unit",
                          f.preset, mesh)};
      c.source = f.source;
      c.unit = "rays per cycle per unit";
      std::string config_path = std::string(RTSIM_CONFIGS_DIR) + "/" + f.preset + ".toml";
      std::string scene_path = shared_scene_path(mesh);
      if (f.rays_per_second == 0) {
        c.skipped = "no published rate";
        out.push_back(c);
        continue;
      }
      if (!std::filesystem::exists(scene_path)) {
        c.skipped = scene_path + " not found";
        out.push_back(c);
        continue;
      }
      progress(fmt::format("presets: {} on the {}", f.preset, mesh));
      double per_unit = f.rays_per_second / (f.rt_cores * f.boost_mhz * 1e6);
      c.expected = per_unit;
      c.lo = per_unit / 2;
      c.hi = per_unit * 2;
      HwConfig config = load_hw_config(config_path);
      Scene scene = load_scene(scene_path);
      BvhImage image = build_bvh_image(scene.mesh, config.bvh);
      std::vector<Ray> rays = sample_camera_rays(scene.mesh, 1920, 1080);
      SimFigures run = simulate(target, {{config, &image, &rays}})[0];
      c.measured = run["rays_per_cycle"] / config.rt_units;
      double nodes = run["type.camera.nodes_per_ray"];
      double ceiling = config.rt.box.count / (run.units_sum("box.issues") / run["rays"]);
      double units = config.rt_units;
      c.detail = fmt::format(
          "configs/{}.toml as it is; {:.2f} nodes a ray; box issues a ray make a box-test ceiling "
          "of {:.3f} rays a cycle per unit ({:.0f}% reached); busy: dispatch {:.0f}%, box units "
          "{:.0f}%, "
          "triangle units {:.0f}%, ray slots {:.0f}%, DRAM {:.0f}%; the band is 2x either way of "
          "{:g} rays/s / ({} RT cores x {} MHz). {}",
          f.preset, nodes, ceiling, 100 * c.measured / ceiling, 100 * run["dispatch.utilisation"],
          100 * run.units_sum("box.utilisation") / units,
          100 * run.units_sum("triangle.utilisation") / units, 100 * run["rt.slot_occupancy"],
          100 * run["dram.utilisation"], f.rays_per_second, f.rt_cores, f.boost_mhz, kMissingCosts);
      c.look_at =
          "the preset's unit counts and latencies against the vendor's part; "
          "utilisation and bottleneck in `rtsim sim` stats";
      out.push_back(c);
    }
  }
  return out;
}

}  // namespace rtsim::validation
