// The energy model on whole runs (model/energy/design_energy.h): DRAM energy per bit of each
// preset, in a run that keeps its bus busy, falls in the band published for its standard
// (model/energy/SOURCES.md, D.5); compressed nodes lower the memory energy per ray, the way AQB8
// reports; and the figures are deterministic, add up, and follow the measured window.
#include <gtest/gtest.h>

#include "tests/sc/sim_test_util.h"

namespace rtsim {
namespace {

// Small caches and one DRAM channel: the run is bound by the DRAM bus.
HwConfig dram_bound(const std::string& preset) {
  HwConfig c = test::small_machine();
  c.rt_units = 4;
  c.rt.warps = 4;
  c.rt.warp_size = 32;
  c.banked_dram = dram_preset_config(preset);
  c.banked_dram.channels = 1;
  return c;
}

double memory_nj_per_ray(const nlohmann::json& doc) {
  const nlohmann::json& s = doc["energy"]["structures"];
  double nj = 0;
  for (const char* name : {"l1", "l1_l2_wires", "l2", "dram"})
    nj += s[name]["dynamic_nj"].get<double>();
  return nj / doc["summary"]["rays"].get<double>();
}

TEST(SimEnergy, DramEnergyPerBitOfEachPresetFallsInItsPublishedBand) {
  test::SimScene s;
  std::vector<Ray> rays = sample_diffuse_rays(s.scene.mesh, 6000, 5);
  struct Band {
    const char* preset;
    double low, high;  // pJ/bit, I/O included (SOURCES.md, D.5)
  };
  for (Band b : {Band{"gddr6-16", 5, 15}, Band{"gddr6-14", 5, 15}, Band{"hbm3-6400", 2.5, 5},
                 Band{"ddr5-4800", 8, 25}, Band{"lpddr5-6400", 3, 15}}) {
    nlohmann::json doc = test::simulate(dram_bound(b.preset), s.scene, rays);
    const nlohmann::json& dram = doc["energy"]["structures"]["dram"];
    double bits = test::stat(doc, "dram.bytes") * 8;
    double pj_per_bit =
        (dram["dynamic_nj"].get<double>() + dram["static_nj"].get<double>()) * 1000 / bits;
    EXPECT_GT(test::stat(doc, "dram.utilisation"), 0.25) << b.preset << ": the bus is busy";
    EXPECT_GE(pj_per_bit, b.low) << b.preset;
    EXPECT_LE(pj_per_bit, b.high) << b.preset;
  }
}

TEST(SimEnergy, CompressedNodesLowerMemoryEnergyPerRay) {
  test::SimScene s;
  std::vector<Ray> rays = sample_diffuse_rays(s.scene.mesh, 4000, 9);
  HwConfig aabb = test::small_machine();
  aabb.bvh.width = 8;
  HwConfig cwbvh = aabb;
  cwbvh.bvh.node_format = NodeFormat::Cwbvh8;
  nlohmann::json wide = test::simulate(aabb, s.scene, rays);
  nlohmann::json compressed = test::simulate(cwbvh, s.scene, rays);
  double ratio = memory_nj_per_ray(compressed) / memory_nj_per_ray(wide);
  EXPECT_LT(ratio, 0.9) << "80-byte nodes against 8 x 32-byte boxes: fewer bytes per node";
  EXPECT_GT(ratio, 0.3) << "AQB8's -70% DRAM accesses is for quantized traversal as well";
}

TEST(SimEnergy, FiguresAreDeterministicAndAddUp) {
  test::SimScene s;
  std::vector<Ray> rays = test::mixed_rays(s.scene, 800, 3);
  HwConfig c = test::small_machine();
  nlohmann::json a = test::simulate(c, s.scene, rays), b = test::simulate(c, s.scene, rays);
  ASSERT_EQ(a["energy"], b["energy"]) << "same inputs, same energy, bit for bit";
  const nlohmann::json& e = a["energy"];
  double dynamic = 0, statics = 0, area = 0, by_type = 0;
  for (const auto& [name, st] : e["structures"].items()) {
    dynamic += st["dynamic_nj"].get<double>();
    statics += st["static_nj"].get<double>();
    area += st["area_mm2"].get<double>();
    EXPECT_GE(st["dynamic_nj"].get<double>(), 0) << name;
  }
  for (const auto& [type, t] : e["by_type"].items()) by_type += t["dynamic_nj"].get<double>();
  EXPECT_NEAR(e["dynamic_nj"].get<double>(), dynamic, 1e-9 * dynamic);
  EXPECT_NEAR(e["static_nj"].get<double>(), statics, 1e-9 * statics);
  EXPECT_NEAR(e["area_mm2"].get<double>(), area, 1e-12);
  EXPECT_NEAR(by_type, dynamic, 1e-9 * dynamic) << "the ray types share all dynamic energy";
  EXPECT_GT(e["structures"]["box_units"]["events"].get<double>(), 0);
  EXPECT_EQ(e["structures"]["box_units"]["events"].get<double>(),
            test::stat(a, "rt0.box.tests") + test::stat(a, "rt1.box.tests"));
  EXPECT_NEAR(e["seconds"].get<double>(), test::stat(a, "cycles") / 1.5e9, 1e-15);

  HwConfig warmed = c;
  warmed.sim.warmup_rays = 400;
  nlohmann::json w = test::simulate(warmed, s.scene, rays);
  EXPECT_LT(w["energy"]["total_nj"].get<double>(), e["total_nj"].get<double>())
      << "the warm-up's events and time are not charged";
  EXPECT_NEAR(w["energy"]["seconds"].get<double>(), test::stat(w, "cycles") / 1.5e9, 1e-15);
}

}  // namespace
}  // namespace rtsim
