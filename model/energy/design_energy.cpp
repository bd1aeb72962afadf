#include "model/energy/design_energy.h"

#include <algorithm>
#include <cmath>

#include "model/energy/dram_energy.h"
#include "model/energy/process_node.h"
#include "model/energy/sram.h"
#include "model/energy/test_units.h"
#include "model/sched/ray_buffer.h"
#include "model/sched/ray_sorter.h"

namespace rtsim {
namespace {

using Json = nlohmann::ordered_json;

// A write of an SRAM bit over a read of it: 1.0-1.4 in the CACTI rows of SOURCES.md (A.3, A.4).
constexpr double kSramWriteOverRead = 1.1;
// Bits of one tag entry (address tag and state); one is read per access (SOURCES.md, A.3: a
// tag access costs about 2% of a line's read).
constexpr uint32_t kTagBits = 32;
// The ray state a traversal step reads from its registers besides two stack entries: origin,
// direction and its inverse, and the hit distance.
constexpr uint32_t kRayRegisterBits = 40 * 8;

// The RT part as the events of a run see it.
struct Run {
  const HwConfig& config;
  const StatsRegistry& stats;
  const ProcessNode& node;
  double seconds;

  double value(const std::string& name) const { return stats.value(name); }
  double units_value(const std::string& suffix) const {  // summed over the RT units
    return stats.units_sum(config.rt_units, "." + suffix);
  }
  double over_run_pj(double mw) const { return mw * seconds * 1e9; }  // mW x s = 1e9 pJ
  double leak_pj(uint64_t sram_bytes) const {
    return over_run_pj(config.energy.sram_leak_mw_per_kb * double(sram_bytes) / 1024);
  }
  // Logic leaks a share of its peak dynamic power (pJ an event x events a cycle x GHz = mW),
  // whatever the run's activity.
  double logic_leak_pj(double pj_per_cycle) const {
    return over_run_pj(config.energy.logic_leak_share * pj_per_cycle * config.clock_ghz);
  }
};

// A pool of test datapaths: each issue of a unit runs issue_width of them.
StructureEnergy test_units(const Run& run, const char* name, const TestUnitConfig& unit,
                           const ArithmeticOps& ops, const char* counter,
                           const char* share_counter) {
  StructureEnergy s{name, "test", share_counter};
  s.instances = run.config.rt_units * unit.count * unit.issue_width;
  s.events = run.units_value(counter);
  double pj = arithmetic_pj(ops, run.node);
  s.dynamic_pj = s.events * pj;
  s.static_pj = run.logic_leak_pj(s.instances * pj);
  s.area_mm2 = s.instances * arithmetic_area_mm2(ops, run.node);
  return s;
}

// Each ray slot's state and on-chip stack, in flip-flops: a step reads the ray and pops and
// pushes an entry.
StructureEnergy ray_registers(const Run& run) {
  const RtCoreConfig& rt = run.config.rt;
  StructureEnergy s{"ray_registers", "step", "trav_nodes"};
  s.instances = run.config.rt_units * rt.warps * rt.warp_size;
  s.events = run.units_value("node_steps") + run.units_value("leaf_steps");
  double step_pj =
      (kRayRegisterBits + 2 * 8 * rt.stack.entry_bytes) * flipflop_pj_per_bit(run.node);
  s.dynamic_pj = s.events * step_pj;
  s.static_pj = run.logic_leak_pj(run.config.rt_units * rt.issue_per_cycle * step_pj);
  double bits = double(ray_state_bytes(rt.stack)) * 8;
  s.area_mm2 = s.instances * bits * flipflop_um2_per_bit(run.node) * 1e-6;
  return s;
}

// An SRAM of `instances` arrays: reads and writes by the bits they move, a tag read per access
// when it is a cache, leakage and area of data and tags.
struct SramTraffic {
  double accesses = 0, read_bytes = 0, write_bytes = 0;
};
// line_bytes 0: a plain RAM without tags.
StructureEnergy sram(const Run& run, const std::string& name, const std::string& share_counter,
                     uint32_t instances, const SramArray& data, uint32_t line_bytes,
                     const SramTraffic& t) {
  StructureEnergy s{name, "access", share_counter};
  s.instances = instances;
  s.events = t.accesses;
  double bit_pj = sram_read_pj(data, run.node) / data.access_bits;
  s.dynamic_pj = (t.read_bytes + kSramWriteOverRead * t.write_bytes) * 8 * bit_pj;
  SramArray tags{line_bytes ? data.bytes / line_bytes * kTagBits / 8 : 0, kTagBits, 1, data.ports};
  if (tags.bytes) s.dynamic_pj += t.accesses * sram_read_pj(tags, run.node);
  s.sram_bytes = instances * (data.bytes + tags.bytes);
  s.static_pj = run.leak_pj(s.sram_bytes);
  s.area_mm2 = instances * (sram_area_mm2(data, run.node) + sram_area_mm2(tags, run.node));
  return s;
}

SramArray cache_array(const CacheConfig& c, uint64_t bytes) {
  return {bytes, 64, c.banks, std::max<uint32_t>(c.bank_ports, 1)};
}

// Bytes between the units' first level and the second level, over wire_mm of wire.
StructureEnergy wires(const Run& run) {
  const std::string& first = run.config.memory[0].name;
  const std::string& second = run.config.memory[1].name;
  StructureEnergy s{first + "_" + second + "_wires", "byte", "mem." + second + ".accesses"};
  s.instances = run.config.rt_units;
  s.events =
      run.value("mem." + second + ".bytes_read") + run.value("mem." + second + ".write_bytes");
  s.dynamic_pj = s.events * 8 * wire_pj_per_bit_mm(run.node) * run.config.energy.wire_mm;
  return s;
}

// A cache level: every slice of every instance, an SRAM array each.
StructureEnergy cache_level(const Run& run, uint32_t index) {
  const MemoryLevelConfig& level = run.config.memory[index];
  const std::string p = "mem." + level.name;
  SramTraffic traffic{run.value(p + ".accesses"), run.value(p + ".bytes_read"),
                      run.value(p + ".bytes_below") + run.value(p + ".write_bytes")};
  uint32_t slices = level_instances(level, run.config.rt_units) * level.slices;
  return sram(run, level.name, p + ".accesses", slices,
              cache_array(level.cache, level.cache.size_bytes / level.slices),
              level.cache.line_bytes, traffic);
}

// The device data scaled to one channel: bursts by their bits, activations by the row, refresh
// and background by capacity (one rank against the device).
StructureEnergy dram(const Run& run) {
  const BankedDramConfig& c = run.config.banked_dram;
  const DramDeviceData& device = dram_energy_device(c.energy_device);
  DramCommandEnergy e = dram_command_energy(device.currents, device.times);
  double burst = c.burst_bytes() * 8 / device.burst_bits;
  double row = c.row_bytes / device.page_bytes;
  double rank_gbit = double(c.banks()) * c.rows * c.row_bytes * 8 / double(1ull << 30);
  double capacity = rank_gbit / device.gbit;
  bool closed = c.page_policy == DramPagePolicy::Closed;
  double background_mw = (closed ? e.precharged_mw : e.active_mw) * capacity * c.ranks;

  StructureEnergy s{"dram", "burst", "dram_bytes"};
  s.instances = c.channels;
  double bytes = run.value("dram.bytes"), act = 0, read = 0, write = 0, refresh = 0;
  double background = run.over_run_pj(c.channels * background_mw);
  if (run.config.dram_model == DramModel::Banked) {
    double rd = run.value("dram.cmd.rd"), wr = run.value("dram.cmd.wr");
    s.events = rd + wr;
    act = run.value("dram.cmd.act") * e.act_pre_pj * row;
    read = rd * e.read_pj * burst;
    write = wr * e.write_pj * burst;
    refresh = (run.value("dram.cmd.ref") + run.value("dram.cmd.ref_pb") / c.banks()) *
              e.refresh_pj * capacity;
  } else {  // one bus: every byte at the streaming read energy; the preset's devices in the
            // share of its bandwidth the bus has
    s.events = bytes / c.burst_bytes();
    read = s.events * e.read_pj * burst;
    background *=
        std::min(1.0, run.config.dram.bytes_per_cycle * run.config.clock_ghz / c.peak_gb_per_s());
  }
  double io = bytes * 8 * c.io_pj_per_bit;
  s.parts_pj = {{"act_pre", act}, {"read", read},       {"write", write},
                {"io", io},       {"refresh", refresh}, {"background", background}};
  s.dynamic_pj = act + read + write + io;
  s.static_pj = refresh + background;  // by time, not by rays
  return s;
}

double type_value(const StatsRegistry& stats, int type, const std::string& counter) {
  return stats.value(std::string("type.") + ray_type_name(RayType(type)) + "." + counter);
}

void split_by_type(DesignEnergy& d, const StatsRegistry& stats) {
  for (int t = 0; t < kRayTypeCount; ++t) d.type_rays[t] = uint64_t(type_value(stats, t, "rays"));
  // Each structure's dynamic energy by the types' shares of its events; by their rays when no
  // type has any (a prefetch's traffic, say), so that the types share all of it.
  for (const StructureEnergy& s : d.structures) {
    std::array<double, kRayTypeCount> share{};
    double all = 0;
    for (const std::string& counter : {s.share_counter, std::string("rays")}) {
      for (int t = 0; t < kRayTypeCount; ++t) {
        share[t] = type_value(stats, t, counter);
        all += share[t];
      }
      if (all > 0) break;
    }
    if (all > 0)
      for (int t = 0; t < kRayTypeCount; ++t) d.type_dynamic_pj[t] += s.dynamic_pj * share[t] / all;
  }
}

double sum(const std::vector<StructureEnergy>& all, double StructureEnergy::*field) {
  double total = 0;
  for (const StructureEnergy& s : all) total += s.*field;
  return total;
}

}  // namespace

double DesignEnergy::dynamic_pj() const {
  return sum(structures, &StructureEnergy::dynamic_pj);
}
double DesignEnergy::static_pj() const {
  return sum(structures, &StructureEnergy::static_pj);
}
double DesignEnergy::area_mm2() const {
  return sum(structures, &StructureEnergy::area_mm2);
}

double DesignEnergy::sram_area_mm2() const {
  double area = 0;
  for (const StructureEnergy& s : structures)
    if (s.sram_bytes) area += s.area_mm2;
  return area;
}

uint64_t DesignEnergy::sram_bytes() const {
  uint64_t bytes = 0;
  for (const StructureEnergy& s : structures) bytes += s.sram_bytes;
  return bytes;
}

DesignEnergy design_energy(const HwConfig& c, const StatsRegistry& stats) {
  DesignEnergy d;
  d.node = c.energy.node;
  d.rays = uint64_t(stats.value("rays"));
  d.seconds = stats.value("cycles") / (c.clock_ghz * 1e9);
  Run run{c, stats, process_node(c.energy.node), d.seconds};

  d.structures.push_back(
      test_units(run, "box_units", c.rt.box, fp32_box_test(), "box.tests", "trav_nodes"));
  d.structures.push_back(test_units(run, "triangle_units", c.rt.triangle, triangle_test(),
                                    "triangle.tests", "trav_prims"));
  d.structures.push_back(test_units(run, "transform_units", c.rt.transform, transform_test(),
                                    "transform.tests", "trav_instances"));
  d.structures.push_back(ray_registers(run));
  d.structures.push_back(cache_level(run, 0));
  if (uint64_t bytes = ray_buffer_sram_bytes(c)) {
    double moved = run.value("treelet_queues.buffer.sram_bytes");
    double reads = run.value("treelet_queues.buffer.sram_reads");
    double accesses = reads + run.value("treelet_queues.buffer.sram_writes");
    double read_share = accesses > 0 ? reads / accesses : 0;  // states move whole
    SramTraffic buffer{accesses, moved * read_share, moved * (1 - read_share)};
    d.structures.push_back(
        sram(run, "ray_buffer", "rays", 1, {bytes, 64, c.treelet_queues.buffer.banks}, 0, buffer));
  }
  if (uint64_t bytes = uint64_t(sort_buffer_bytes(c.sort))) {  // each ray written and read once
    double rays = run.value("sort.rays");
    SramTraffic sort{2 * rays, rays * kSortedRayBytes, rays * kSortedRayBytes};
    d.structures.push_back(sram(run, "sort_buffer", "rays", 1, {bytes}, 0, sort));
  }
  if (c.memory.size() > 1) d.structures.push_back(wires(run));
  for (uint32_t i = 1; i < c.memory.size(); ++i) d.structures.push_back(cache_level(run, i));
  d.structures.push_back(dram(run));
  split_by_type(d, stats);
  return d;
}

Json design_energy_json(const DesignEnergy& d) {
  auto nj = [](double pj) { return pj / 1000; };
  double joules = d.total_pj() * 1e-12;
  Json per_ray = d.rays ? Json(nj(d.total_pj()) / double(d.rays)) : Json();  // null: no rays
  Json doc = {{"node", d.node},
              {"seconds", d.seconds},
              {"total_nj", nj(d.total_pj())},
              {"dynamic_nj", nj(d.dynamic_pj())},
              {"static_nj", nj(d.static_pj())},
              {"nj_per_ray", per_ray},
              {"mrays_per_joule", joules > 0 ? double(d.rays) / joules / 1e6 : 0},
              {"power_w", d.seconds > 0 ? joules / d.seconds : 0},
              {"area_mm2", d.area_mm2()},
              {"sram_area_mm2", d.sram_area_mm2()},
              {"sram_bytes", d.sram_bytes()}};
  Json structures = Json::object();
  for (const StructureEnergy& s : d.structures) {
    structures[s.name] = {{"event", s.event},
                          {"instances", s.instances},
                          {"events", s.events},
                          {"pj_per_event", s.events > 0 ? s.dynamic_pj / s.events : 0},
                          {"dynamic_nj", nj(s.dynamic_pj)},
                          {"static_nj", nj(s.static_pj)},
                          {"area_mm2", s.area_mm2},
                          {"sram_bytes", s.sram_bytes}};
    for (const auto& [part, pj] : s.parts_pj) structures[s.name]["parts_nj"][part] = nj(pj);
  }
  doc["structures"] = structures;
  Json types = Json::object();
  for (int t = 0; t < kRayTypeCount; ++t)
    if (d.type_rays[t])
      types[ray_type_name(RayType(t))] = {
          {"dynamic_nj", nj(d.type_dynamic_pj[t])},
          {"dynamic_nj_per_ray", nj(d.type_dynamic_pj[t]) / double(d.type_rays[t])}};
  doc["by_type"] = types;
  return doc;
}

}  // namespace rtsim
