// The hardware config of a simulation: the RT units and their test units, the cache levels
// (model/mem/hierarchy.h) and DRAM, the ray dispatcher, the treelet queues and the BVH the hardware
// traverses. The TOML nesting follows the module tree (rt.l1 is each RT unit's L1). Every key is
// read in one place, read_hw_config() in hw_config.cpp, with its default, unit and description;
// model/SIM-REFERENCE.md lists them all, and `rtsim sim --list-keys` prints them.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/bvh/bvh_config.h"
#include "model/energy/energy_config.h"
#include "model/mem/cache.h"
#include "model/mem/crossbar.h"
#include "model/mem/dram.h"
#include "model/mem/dram_config.h"
#include "model/mem/hierarchy.h"
#include "model/sched/dispatcher.h"
#include "model/sched/ray_sorter.h"
#include "model/sched/rt_core.h"
#include "model/sched/shader_core.h"
#include "model/sched/treelet_scheduler.h"

namespace rtsim {

// The limits of a cache's size_bytes (memory.NAME), also for the sizes `rtsim curve` sets.
constexpr uint64_t kMinCacheBytes = 64;
constexpr uint64_t kMaxCacheBytes = 1ull << 34;

struct SimulationConfig {
  uint32_t quantum_cycles = 16;  // cycles: how far a unit runs ahead of SystemC time
  uint64_t stall_cycles =
      200000;                // cycles: no progress (nor anything scheduled) for this long: a stall
  uint64_t warmup_rays = 0;  // rays: the stream's first rays, timed but not measured
  uint32_t warmup_frames = 0;  // frames: the stream's first frames, likewise
};

// simple: one data bus, a fixed latency (model/mem/dram.h); banked: channels, banks, row
// buffers, refresh and a scheduling controller (model/mem/dram_controller.h).
enum class DramModel : uint8_t { Simple, Banked };

// The banked DRAM of a preset of configs/dram/ (dram_presets.h). Throws InputError naming the
// preset for an unknown name.
BankedDramConfig dram_preset_config(const std::string& name);
const BankedDramConfig& default_banked_dram();  // the gddr6-16 preset

// The two levels of a config that gives none: l1 (per unit) and l2 (shared), as the shorthand
// sections [rt.l1], [xbar] and [l2] describe them.
std::vector<MemoryLevelConfig> default_memory_levels();

struct HwConfig {
  std::string name = "default";  // the preset's name, carried into results
  std::string description;
  double clock_ghz = 1.5;  // GHz: the clock of every unit (MRays/s = rays/cycle * clock)
  SimulationConfig sim;
  DispatchConfig dispatch;
  SortConfig sort;        // the ray sorting unit between dispatch and the units (off by default)
  uint32_t rt_units = 4;  // units: RT units, each with its own first cache level
  RtCoreConfig rt;
  TreeletQueueConfig treelet_queues;
  // The cache levels from the unit outwards: by default a 32 KB L1 per unit and a 2 MB shared L2.
  std::vector<MemoryLevelConfig> memory = default_memory_levels();
  DramModel dram_model = DramModel::Banked;
  DramConfig dram{64.0, 200, 128};                       // the simple model
  BankedDramConfig banked_dram = default_banked_dram();  // the banked model
  BvhConfig bvh;
  ShaderConfig shader;  // the SM around each RT unit (off by default)
  EnergyConfig energy;  // the energy and area model's node and assumptions
};

// The cache levels as the simulator builds them: write-back, but every level below a shared
// one write-through in treelet mode, where a ray moves between units and so its spilled stack
// entries must reach a level every unit reads.
std::vector<MemoryLevelConfig> levels_as_built(const HwConfig& config);
// The unit's first level and the level above DRAM (the same level in a one-level hierarchy).
inline MemoryLevelConfig& first_level(HwConfig& c) {
  return c.memory.front();
}
inline const MemoryLevelConfig& first_level(const HwConfig& c) {
  return c.memory.front();
}
inline MemoryLevelConfig& last_level(HwConfig& c) {
  return c.memory.back();
}
inline const MemoryLevelConfig& last_level(const HwConfig& c) {
  return c.memory.back();
}
// The level named `name`, or null.
const MemoryLevelConfig* find_level(const HwConfig& config, const std::string& name);
// Whether the hierarchy is a unit level and one shared level, the form the faster fidelity
// levels and the energy model's wire term reason with; else why not, naming the command.
std::string two_level_problem(const HwConfig& config, const std::string& what);
// Bytes of the treelet queues' SRAM ray buffer (0 outside treelet mode and in memory).
uint64_t ray_buffer_sram_bytes(const HwConfig& config);
// Ray slots of the machine: the rays it holds in flight (ray contexts; the treelet buffer in
// treelet mode; the sorting buffer's rays too). Sizes the sampled level's windows too.
uint32_t ray_slots(const HwConfig& config);

// Host memory that building a simulation of the config takes (model/sc/rt_simulator.cpp: the
// RT units, their ray contexts, every cache's tags and sectors, the sorting unit's bins, the
// SMs' warp slots), and the key that takes most of it, for load_hw_config's memory plan
// (traces/memory_plan.h).
struct SimHostMemory {
  uint64_t bytes = 0;
  std::string largest;  // e.g. "memory.l2.size_bytes"
};
SimHostMemory sim_host_memory(const HwConfig& config);

// One key's documentation (for model/SIM-REFERENCE.md and --list-keys).
struct HwConfigKey {
  std::string key, type, default_value, unit, description;
};

// Loads a TOML file (path empty: the defaults) and applies the "key=value" overrides.
// Throws InputError naming the file (or the --set) and line for a syntax error, a wrong type,
// a value out of range, an unknown key, an impossible combination, or a machine whose
// simulation would not fit the memory available (sim_host_memory).
HwConfig load_hw_config(const std::string& path, const std::vector<std::string>& overrides = {});

// What an error about a problem of the loaded config names: the overrides ("--set A=1 --set
// B=2") when the file alone is free of it (problem_of returns empty), else the file
// ("(defaults)" without one).
std::string config_culprit(const std::string& path, const std::vector<std::string>& overrides,
                           const std::function<std::string(const HwConfig&)>& problem_of);

// Every key of the config, in file order, with its default.
std::vector<HwConfigKey> hw_config_keys();

// The config with every key resolved: as TOML (each key commented with its unit and
// description) and as nested JSON.
std::string resolved_toml(const HwConfig& config);
nlohmann::ordered_json resolved_json(const HwConfig& config);

// The one-bus DRAM the faster fidelity levels (model/fidelity/) reason with: config.dram with
// the simple model; with the banked one, its peak bandwidth and the unloaded latency of a read
// to a closed bank (tRCD + tCL + a burst, and controller_latency).
DramConfig dram_for_analysis(const HwConfig& config);
// Cycles of a read of `bytes` from such a DRAM with nothing else queued: its latency and the
// transfer (none without a bandwidth limit).
inline double unloaded_dram_read(const DramConfig& dram, uint32_t bytes) {
  return dram.latency + (dram.bytes_per_cycle > 0 ? double(bytes) / dram.bytes_per_cycle : 0.0);
}

// Why the combination is impossible (empty if fine), naming the section.
std::string hw_config_problem(const HwConfig& config);

}  // namespace rtsim
