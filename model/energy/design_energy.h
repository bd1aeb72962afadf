// Energy and area of a design point from a run's event counts (issue 20): each structure of
// the RT part (test units, ray registers, L1s, treelet ray buffer, wires to the L2, L2 slices,
// DRAM) is charged per event at the energies of model/energy/ (SOURCES.md gives every figure's
// source), plus its static power over the measured time; areas at the config's process node.
// Dynamic energy is also split by ray type, in proportion to each type's share of the events
// that drive a structure (nodes visited for box tests, L2 accesses for the L2...). The model
// and what it leaves out are described in model/energy/README.md.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/config/hw_config.h"
#include "model/sched/stats_registry.h"
#include "traces/ray.h"

namespace rtsim {

struct StructureEnergy {
  StructureEnergy(std::string name, std::string event, std::string share_counter)
      : name(std::move(name)), event(std::move(event)), share_counter(std::move(share_counter)) {}
  std::string name;           // a cache level's name, "dram", ...
  std::string event;          // what one event is: "test", "access", "burst", "byte"
  std::string share_counter;  // type.T.NAME: the ray types' share of its dynamic energy
  uint32_t instances = 0;     // datapaths, caches, slices, channels
  double events = 0;          // over the run, all instances
  double dynamic_pj = 0;      // over the run
  double static_pj = 0;       // static power over the measured time
  double area_mm2 = 0;        // all instances; 0 off chip (DRAM)
  uint64_t sram_bytes = 0;    // SRAM arrays it holds (data and tags)
  // Where the energy went, where it has parts (DRAM: ACT+PRE, RD, WR and I/O, dynamic;
  // refresh and background, static).
  std::vector<std::pair<std::string, double>> parts_pj;
};

struct DesignEnergy {
  std::string node;
  double seconds = 0;  // measured cycles at the clock
  uint64_t rays = 0;
  std::vector<StructureEnergy> structures;
  std::array<double, kRayTypeCount> type_dynamic_pj{};  // dynamic energy by ray type
  std::array<uint64_t, kRayTypeCount> type_rays{};

  double dynamic_pj() const;
  double static_pj() const;
  double total_pj() const { return dynamic_pj() + static_pj(); }
  double area_mm2() const;       // on chip: units, registers, SRAM
  double sram_area_mm2() const;  // the SRAM arrays alone
  uint64_t sram_bytes() const;
};

// From the stats of a cycle-level run (warm-up already subtracted) and its config.
DesignEnergy design_energy(const HwConfig& config, const StatsRegistry& stats);

// The stats document's "energy" section (schema in model/SIM.md).
nlohmann::ordered_json design_energy_json(const DesignEnergy& energy);

}  // namespace rtsim
