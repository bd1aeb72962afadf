// RT unit: traversal control of the rays in its slots, driving the functional traversal
// (model/units/traversal.h) one step at a time, so every timed ray computes exactly the answer
// `rtsim verify` checks. Plain C++ with no SystemC; model/sc/rt_unit_module.h wraps it.
// Modes: per-ray depth-first (each ray steps on its own, as in today's RT cores), treelet
// queues (a ray about to enter another treelet is postponed: Aila & Karras, HPG 2010), and
// warp-coherent packets (the rays of a warp step together, SIMT "while-while" traversal as in
// Aila & Laine, HPG 2009; the CMU 15-462 ray tracing lecture's SIMD efficiency).
// Timing of one step: it starts when traversal control has an issue slot (issue_per_cycle per
// cycle), reads the node (or the leaf's triangles, one read) through the L1 port, passes the
// ray-box (or ray-triangle) unit pool once the data is there, and the next step can start
// control_latency cycles after the tests finish. A fresh ray first spends setup_latency cycles
// in ray setup. Stack spills and refills follow hardware_stack.h. The unit does work only at
// the cycles in its event queue: nothing happens on idle cycles.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/mem/cache.h"
#include "model/sched/event_queue.h"
#include "model/sched/hardware_stack.h"
#include "model/sched/ray_supply.h"
#include "model/sched/test_unit_pool.h"
#include "model/units/traversal.h"

namespace rtsim {

enum class TraversalMode : uint8_t { DepthFirst, Treelet, Packet };
// Packet mode: which lanes step together. node_first: every lane with a node to visit, and
// leaves only when no lane has a node (while-while); majority: the kind more lanes need.
enum class PacketPolicy : uint8_t { NodeFirst, Majority };

const char* traversal_mode_name(TraversalMode mode);  // depth_first, treelet, packet
const char* packet_policy_name(PacketPolicy policy);  // node_first, majority

struct RtCoreConfig {
  TraversalMode mode = TraversalMode::DepthFirst;
  uint32_t warps = 4;            // warps: warp slots of the unit
  uint32_t warp_size = 32;       // rays: rays per warp (ray slots = warps * warp_size)
  uint32_t issue_per_cycle = 2;  // steps: steps (packet mode: warp steps) started per cycle
  uint32_t setup_latency = 4;    // cycles: ray setup, from arrival to the first step
  uint32_t control_latency = 1;  // cycles: stack pop, sort and push after the tests
  StackConfig stack;
  TestUnitConfig box{1, 8, 8};        // ray-box units: a BVH8 node per issue
  TestUnitConfig triangle{1, 1, 12};  // ray-triangle units
  PacketPolicy packet_policy = PacketPolicy::NodeFirst;
};

std::string rt_core_config_problem(const RtCoreConfig& config);

// Where a unit reads its cache counters to charge each ray its share (may be null).
struct MemoryProbe {
  const CacheStats* l1 = nullptr;
  const CacheStats* l2 = nullptr;
};

struct RtCoreStats {
  uint64_t rays_started = 0, rays_retired = 0;
  uint64_t node_steps = 0, leaf_steps = 0;
  uint64_t issue_stalls = 0;              // step starts deferred a cycle by the issue width
  uint64_t fetches = 0, fetch_bytes = 0;  // reads to the L1 (packet mode: after coalescing)
  uint64_t spill_writes = 0, spill_entries = 0, refill_reads = 0, refill_entries = 0;
  uint64_t postponed = 0, refused = 0;  // treelet mode: rays queued, rays a full queue refused
  uint64_t warp_steps = 0, active_lanes = 0;  // packet mode
  uint64_t node_warp_steps = 0, distinct_nodes = 0;
  double ray_slot_cycles = 0;  // integral of occupied ray slots over cycles
  Cycle last_cycle = 0;        // the last cycle the unit did anything
};

class RtCore {
public:
  RtCore(uint32_t id, const RtCoreConfig& config, const TraversalUnit& traversal, RayMemory& memory,
         MemoryProbe probe = {});

  void set_supply(RaySupply* supply) { supply_ = supply; }
  // Asks for rays at cycle now (also after a "work available" notice); returns progress made.
  uint64_t poll(Cycle now);
  // Handles every event before cycle `until`; returns the progress made (rays taken, steps,
  // rays retired). Zero progress over a long stretch means a stall.
  uint64_t advance(Cycle until);

  bool has_event() const { return !events_.empty(); }
  Cycle next_event() const { return events_.next_cycle(); }
  bool started() const { return started_; }
  bool waiting() const { return waiting_; }  // has free slots the supply could not fill yet
  bool finished() const { return in_flight_ == 0 && events_.empty() && !waiting_ && started_; }
  uint32_t in_flight() const { return in_flight_; }
  uint32_t slots() const { return uint32_t(slots_.size()); }

  const RtCoreStats& stats() const { return stats_; }
  const TestUnitPool& box() const { return box_; }
  const TestUnitPool& triangle() const { return triangle_; }
  const RtCoreConfig& config() const { return config_; }
  uint32_t id() const { return id_; }
  std::string dump() const;  // what every ray is doing, for stall reports
  void account(Cycle now);   // counts slot occupancy up to now

private:
  struct Next {
    bool live = false;  // an entry that step() will visit (not culled)
    bool leaf = false;
    uint32_t depth = 0;  // its position in the stack
  };
  Next peek(const TraversalState& state) const;
  // The cycle traversal control can start a step asked for at `now`: now, or the first later
  // cycle with a free issue slot (reserved, so the step is scheduled once, not retried).
  Cycle reserve_issue(Cycle now);
  // Whether slot or warp `item` may step at `now`; if not, it is scheduled at its issue cycle.
  bool claim_issue(uint32_t item, Cycle now);
  void fill(Cycle now);
  void install(RayContext* ray, uint32_t slot, Cycle now);
  void retire(uint32_t slot, Cycle now);
  void release(uint32_t slot, Cycle now);
  void on_ray(uint32_t slot, Cycle now);
  void on_warp(uint32_t warp, Cycle now);
  Cycle read(RayContext& ray, uint64_t addr, uint32_t bytes, Cycle now);
  Cycle fetch(RayContext& ray, const StepResult& step, Cycle now);
  bool refill(RayContext& ray, const Next& next, Cycle now, Cycle& ready);
  uint32_t treelet_of(const RayContext& ray, const Next& next) const;
  void settle(RayContext& ray, uint32_t kept, uint32_t visited_treelet, Cycle now);
  void check_kind(const StepResult& step, const Next& next) const;

  uint32_t id_;
  RtCoreConfig config_;
  const TraversalUnit& traversal_;
  const std::vector<uint32_t>& node_treelet_;
  RayMemory& memory_;
  MemoryProbe probe_;
  RaySupply* supply_ = nullptr;
  HardwareStack stack_;
  TestUnitPool box_, triangle_;
  EventQueue events_;
  std::vector<RayContext*> slots_;    // warps * warp_size
  std::vector<uint32_t> warp_live_;   // rays still in each warp (per-ray and packet modes)
  std::vector<Cycle> issue_granted_;  // per slot (packet mode: per warp): a reserved issue
  std::vector<uint32_t> free_slots_;  // treelet mode
  std::vector<uint32_t> free_warps_;  // per-ray and packet modes
  std::vector<RayContext*> batch_;
  std::vector<Next> lane_next_;  // packet mode scratch
  std::vector<uint32_t> lane_tests_;
  std::vector<uint64_t> warp_reads_;
  uint32_t in_flight_ = 0;
  bool waiting_ = false, started_ = false;
  Cycle now_ = 0;  // the latest cycle handled: the unit's local time
  Cycle issue_cycle_ = 0;
  uint32_t issued_ = 0;
  uint64_t progress_ = 0;
  Cycle occupancy_since_ = 0;
  RtCoreStats stats_;
};

}  // namespace rtsim
