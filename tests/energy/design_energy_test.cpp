// A design point's energy from event counts (model/energy/design_energy.h), on hand-made stats:
// each event is charged at its source's energy, DRAM commands are scaled from the data-sheet
// device to the preset's channel, leakage runs over the measured time, and the ray types share
// the dynamic energy by their events.
#include <gtest/gtest.h>

#include "model/energy/design_energy.h"
#include "model/energy/dram_energy.h"
#include "model/energy/sram.h"
#include "model/energy/test_units.h"

namespace rtsim {
namespace {

const StructureEnergy& structure(const DesignEnergy& d, const std::string& name) {
  for (const StructureEnergy& s : d.structures)
    if (s.name == name) return s;
  throw std::runtime_error("no structure " + name);
}

double part(const StructureEnergy& s, const std::string& name) {
  for (const auto& [part, pj] : s.parts_pj)
    if (part == name) return pj;
  throw std::runtime_error("no part " + name);
}

// 1 ms at the default 1.5 GHz, 1000 rays.
StatsRegistry one_millisecond() {
  StatsRegistry r;
  r.counter("cycles", 1500000);
  r.counter("rays", 1000);
  return r;
}

TEST(DesignEnergy, ChargesEachTestAtItsArithmeticEnergy) {
  HwConfig c;
  StatsRegistry r = one_millisecond();
  r.counter("rt0.box.tests", 600);
  r.counter("rt3.box.tests", 400);
  r.counter("rt1.triangle.tests", 100);
  DesignEnergy d = design_energy(c, r);
  const ProcessNode& node = process_node("7nm");
  EXPECT_DOUBLE_EQ(structure(d, "box_units").dynamic_pj,
                   1000 * arithmetic_pj(fp32_box_test(), node));
  EXPECT_DOUBLE_EQ(structure(d, "triangle_units").dynamic_pj,
                   100 * arithmetic_pj(triangle_test(), node));
  EXPECT_EQ(structure(d, "box_units").instances,
            c.rt_units * c.rt.box.count * c.rt.box.issue_width);
  // Static: a tenth of the datapaths' peak power (pJ x GHz = mW) for 1 ms.
  double peak_mw = 32 * arithmetic_pj(fp32_box_test(), node) * 1.5;
  EXPECT_NEAR(structure(d, "box_units").static_pj, 0.1 * peak_mw * 1e-3 * 1e9, 1e-6);
  EXPECT_DOUBLE_EQ(d.seconds, 1e-3);
}

TEST(DesignEnergy, ScalesDramCommandsFromTheDeviceToThePresetsChannel) {
  HwConfig c;  // gddr6-16: 32-byte bursts, 2 KB rows, 4 Gb per channel; GDDR5X's currents
  ASSERT_EQ(c.banked_dram.energy_device, "gddr5x-8gb-x32");
  StatsRegistry r = one_millisecond();
  r.counter("dram.cmd.act", 10);
  r.counter("dram.cmd.rd", 100);
  r.counter("dram.cmd.wr", 20);
  r.counter("dram.cmd.ref", 1);
  r.counter("dram.cmd.ref_pb", 32);
  r.counter("dram.bytes", 120 * 32);
  DesignEnergy d = design_energy(c, r);
  const StructureEnergy& dram = structure(d, "dram");
  const DramDeviceData& device = gddr5x_8gb_x32();
  DramCommandEnergy e = dram_command_energy(device.currents, device.times);
  // The device's burst is 512 bits against the channel's 256, its page 4 KB against 2 KB, its
  // 8 Gb against 16 banks x 16384 rows x 2 KB = 4 Gb: each a half.
  EXPECT_DOUBLE_EQ(part(dram, "act_pre"), 10 * e.act_pre_pj / 2);
  EXPECT_DOUBLE_EQ(part(dram, "read"), 100 * e.read_pj / 2);
  EXPECT_DOUBLE_EQ(part(dram, "write"), 20 * e.write_pj / 2);
  EXPECT_DOUBLE_EQ(part(dram, "refresh"), (1 + 32.0 / 16) * e.refresh_pj / 2);
  EXPECT_DOUBLE_EQ(part(dram, "io"), 120 * 32 * 8 * 6.0);
  EXPECT_EQ(dram.events, 120);
  // Static: refresh, and open pages' active standby for 1 ms, per channel.
  EXPECT_NEAR(dram.static_pj, part(dram, "refresh") + 8 * e.active_mw / 2 * 1e-3 * 1e9, 1e-3);
  EXPECT_NEAR(part(dram, "background"), 8 * e.active_mw / 2 * 1e-3 * 1e9, 1e-3);
  EXPECT_DOUBLE_EQ(dram.dynamic_pj, part(dram, "act_pre") + part(dram, "read") +
                                        part(dram, "write") + part(dram, "io"));
  EXPECT_EQ(dram.area_mm2, 0) << "off chip";
}

TEST(DesignEnergy, SimpleDramChargesItsBytesAtTheStreamingReadEnergy) {
  HwConfig c;
  c.dram_model = DramModel::Simple;
  StatsRegistry r = one_millisecond();
  r.counter("dram.bytes", 6400);
  r.counter("dram.cmd.act", 99);  // not the simple model's: ignored
  DesignEnergy d = design_energy(c, r);
  const StructureEnergy& dram = structure(d, "dram");
  DramCommandEnergy e = dram_command_energy(gddr5x_8gb_x32().currents, gddr5x_8gb_x32().times);
  EXPECT_DOUBLE_EQ(dram.dynamic_pj, 200 * e.read_pj / 2 + 6400 * 8 * 6.0);
  // The preset's devices in the bus's share of their bandwidth: 64 B/cycle x 1.5 GHz = 96 GB/s
  // of gddr6-16's 256.
  EXPECT_NEAR(dram.static_pj, 8 * e.active_mw / 2 * 96.0 / 256 * 1e-3 * 1e9, 1e-3);
}

TEST(DesignEnergy, CachesChargeBitsMovedTagsAndLeakage) {
  HwConfig c;
  StatsRegistry r = one_millisecond();
  r.counter("mem.l2.accesses", 1000);
  r.counter("mem.l2.bytes_read", 64000);
  r.counter("mem.l2.bytes_below", 6400);  // fills from DRAM
  r.counter("mem.l2.write_bytes", 640);
  DesignEnergy d = design_energy(c, r);
  const StructureEnergy& l2 = structure(d, "l2");
  const ProcessNode& node = process_node("7nm");
  double bit =
      sram_read_pj({last_level(c).cache.size_bytes, 64, last_level(c).cache.banks}, node) / 64;
  uint64_t tag_bytes = last_level(c).cache.size_bytes / 64 * 4;
  double tag = sram_read_pj({tag_bytes, 32, 1}, node);
  EXPECT_NEAR(l2.dynamic_pj, (64000 + 1.1 * 7040) * 8 * bit + 1000 * tag, 1e-6);
  EXPECT_EQ(l2.sram_bytes, last_level(c).cache.size_bytes + tag_bytes);
  EXPECT_NEAR(l2.static_pj,
              0.4 * (last_level(c).cache.size_bytes + tag_bytes) / 1024.0 * 1e-3 * 1e9, 1e-3);
  // The wires carry what the L2 sends up and takes down: 5 mm at 0.75 V.
  EXPECT_NEAR(structure(d, "l1_l2_wires").dynamic_pj,
              64640 * 8 * 0.121 * (0.75 / 0.9) * (0.75 / 0.9) * 5, 1e-6);
  // A bigger L2 leaks and takes more area, and each bit costs more to read.
  last_level(c).cache.size_bytes *= 4;
  const StructureEnergy bigger = structure(design_energy(c, r), "l2");  // a copy
  EXPECT_NEAR(bigger.static_pj / l2.static_pj, 4, 1e-9);
  EXPECT_GT(bigger.area_mm2, 3.9 * l2.area_mm2);
  EXPECT_GT(bigger.dynamic_pj, l2.dynamic_pj);
}

TEST(DesignEnergy, AnOlderNodeCostsMoreEnergyAndArea) {
  HwConfig c;
  StatsRegistry r = one_millisecond();
  r.counter("rt0.box.tests", 1000);
  r.counter("mem.l1.accesses", 1000);
  r.counter("mem.l1.bytes_read", 64000);
  DesignEnergy n7 = design_energy(c, r);
  c.energy.node = "45nm";
  DesignEnergy n45 = design_energy(c, r);
  EXPECT_NEAR(structure(n7, "box_units").dynamic_pj / structure(n45, "box_units").dynamic_pj,
              logic_energy_scale(process_node("7nm")), 1e-12);
  EXPECT_NEAR(structure(n7, "l1").dynamic_pj / structure(n45, "l1").dynamic_pj,
              sram_energy_scale(process_node("7nm")), 1e-12);
  EXPECT_NEAR(n7.sram_area_mm2() / n45.sram_area_mm2(), 0.027 / 0.346, 1e-12);
  EXPECT_NEAR(structure(n7, "box_units").area_mm2 / structure(n45, "box_units").area_mm2, 0.059,
              1e-12);
}

TEST(DesignEnergy, RayTypesShareEachStructuresEnergyByTheirEvents) {
  HwConfig c;
  StatsRegistry r = one_millisecond();
  r.counter("rt0.box.tests", 1000);
  r.counter("type.camera.rays", 10);
  r.counter("type.camera.trav_nodes", 300);
  r.counter("type.shadow.rays", 40);
  r.counter("type.shadow.trav_nodes", 100);
  DesignEnergy d = design_energy(c, r);
  double box = structure(d, "box_units").dynamic_pj;
  EXPECT_NEAR(d.type_dynamic_pj[int(RayType::Camera)], 0.75 * box, 1e-9);
  EXPECT_NEAR(d.type_dynamic_pj[int(RayType::Shadow)], 0.25 * box, 1e-9);
  nlohmann::ordered_json doc = design_energy_json(d);
  EXPECT_NEAR(doc["by_type"]["camera"]["dynamic_nj_per_ray"].get<double>(), 0.75 * box / 1000 / 10,
              1e-12);
  EXPECT_FALSE(doc["by_type"].contains("ao")) << "types without rays are left out";
  StatsRegistry none;
  none.counter("cycles", 1000);
  EXPECT_TRUE(design_energy_json(design_energy(c, none))["nj_per_ray"].is_null()) << "no rays";
  EXPECT_NEAR(doc["total_nj"].get<double>(), d.total_pj() / 1000, 1e-12);
  EXPECT_NEAR(doc["mrays_per_joule"].get<double>(), 1000 / (d.total_pj() * 1e-12) / 1e6, 1e-9);
  EXPECT_NEAR(doc["power_w"].get<double>(), d.total_pj() * 1e-12 / 1e-3, 1e-12);
}

TEST(DesignEnergy, ASortingUnitsBufferIsAnSramWrittenAndReadOncePerRay) {
  HwConfig c;
  StatsRegistry r = one_millisecond();
  r.counter("sort.rays", 500);
  DesignEnergy none = design_energy(c, r);
  for (const StructureEnergy& s : none.structures) EXPECT_NE(s.name, "sort_buffer");
  c.sort.key = SortKey::OctantCell;
  DesignEnergy sorted = design_energy(c, r);
  const StructureEnergy& buffer = structure(sorted, "sort_buffer");
  uint64_t bytes = uint64_t(c.sort.buffer_rays) * kSortedRayBytes;
  double bit = sram_read_pj({bytes}, process_node("7nm")) / 64;
  EXPECT_NEAR(buffer.dynamic_pj, 500 * 40 * 8 * bit * (1 + 1.1), 1e-6);
  EXPECT_EQ(buffer.sram_bytes, bytes) << "a RAM: no tags";
  EXPECT_EQ(sorted.sram_bytes(), none.sram_bytes() + bytes);
}

}  // namespace
}  // namespace rtsim
