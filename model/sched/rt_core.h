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
// Memory: a read the L1 cannot answer at once (a miss, or a merge into one) leaves its ray
// (packet mode: its packet) waiting; the L1 reports the data's cycle later (read_done), and the
// step goes on at that cycle. Data reported for a cycle the unit has already passed (it runs up
// to a quantum ahead of simulated time) is used at the unit's local cycle, counted as late.
// The test units are booked when the data is reported (their calendar takes any order).
// Two levels (model/bvh/two_level.h): a top-level leaf is an instance step: the instance
// record's read, then a pass of the transform unit pool (like a test unit, a ray per test),
// which moves the ray into the BLAS; treelets are numbered across both levels.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/mem/cache.h"
#include "model/sched/event_queue.h"
#include "model/sched/hardware_stack.h"
#include "model/sched/ray_supply.h"
#include "model/sched/test_unit_pool.h"
#include "model/sched/treelet_prefetcher.h"
#include "model/units/traversal.h"

namespace rtsim {

enum class TraversalMode : uint8_t { DepthFirst, Treelet, Packet };
// Packet mode: which lanes step together. node_first: every lane with a node to visit, and
// leaves only when no lane has a node (while-while); majority: the kind more lanes need.
enum class PacketPolicy : uint8_t { NodeFirst, Majority };

// Depth-first mode: when a unit takes new rays: once every ray of a warp has retired (warp: the
// warp's slots are refilled together, as a shader core issues a warp), or into each slot as its
// ray retires (slot). Treelet mode always refills slots, packet mode always warps.
enum class Refill : uint8_t { Warp, Slot };

// Who takes the ray-box and ray-triangle issues: separate pools (rt.box and rt.triangle units,
// as NVIDIA's RT cores and Intel's RT units have them), or shared: rt.box.count units each
// start one issue a cycle, of either rt.box.issue_width boxes or rt.triangle.issue_width
// triangles (AMD's ray accelerator: 4 box or 1 triangle test a clock, RDNA4 8 or 2).
enum class TestIssue : uint8_t { Separate, Shared };

const char* traversal_mode_name(TraversalMode mode);  // depth_first, treelet, packet
const char* refill_name(Refill refill);               // warp, slot
const char* test_issue_name(TestIssue issue);         // separate, shared
const char* packet_policy_name(PacketPolicy policy);  // node_first, majority

// Packet mode: packet reordering after Boulos et al., "Adaptive ray packet reordering" (IEEE
// RT 2008). When the lanes a packet step would use fall below `below` of its width, its rays
// are regrouped (lanes of the step's kind first, by the node they visit next), which takes
// `latency` cycles, and it goes on as two packets of half the width, down to min_width lanes;
// the packets step independently, each its own issue. The buffer is the warp's own lanes.
struct PacketReorderConfig {
  double below = 0;        // fraction of the packet's lanes; 0: never reorder
  uint32_t min_width = 8;  // lanes: the narrowest packet
  uint32_t latency = 2;    // cycles: the regrouping
};

// Any-hit shader calls (alpha-tested triangles, traces/alpha.h). After a leaf's tests, each
// candidate on an alpha-tested triangle goes to the shader core and back, one call after another
// in the order the tests found them (a ray's any-hit calls are ordered, as in DXR), for closest-
// and any-hit queries alike. A call takes an issue slot of the shader pool (`shader.count` calls
// start a cycle) and answers `shader.latency` cycles later: the hand-off, the shader and the
// answer. The shader reads the mask's texel, `read_bytes` at its address in the texture region
// (model/mem/memory_level.h), through the unit's L1: the RT unit sits beside its shader core and
// shares its L1, as on NVIDIA's SMs. The model issues those reads with the leaf's own read (a
// unit's reads go out in its local time order), so their latency overlaps the leaf's fetch
// rather than following the tests.
struct AnyHitConfig {
  TestUnitConfig shader{1, 1, 60};
  uint32_t read_bytes = 4;  // bytes: an RGBA8 texel, nearest sampling
};

struct RtCoreConfig {
  TraversalMode mode = TraversalMode::DepthFirst;
  uint32_t warps = 4;            // warps: warp slots of the unit
  uint32_t warp_size = 32;       // rays: rays per warp (ray slots = warps * warp_size)
  uint32_t issue_per_cycle = 2;  // steps: steps (packet mode: warp steps) started per cycle
  uint32_t setup_latency = 4;    // cycles: ray setup, from arrival to the first step
  uint32_t control_latency = 1;  // cycles: stack pop, sort and push after the tests
  StackConfig stack;
  TestUnitConfig box{1, 8, 8};                 // ray-box units: a BVH8 node per issue
  TestUnitConfig triangle{1, 1, 12};           // ray-triangle units
  TestIssue test_issue = TestIssue::Separate;  // shared: triangle.count must equal box.count
  // Instance transform units (two levels): a ray per issue; assumed as deep as the box test
  // (three chained multiply-adds a component, no published figure).
  TestUnitConfig transform{1, 1, 8};
  PacketPolicy packet_policy = PacketPolicy::NodeFirst;
  PacketReorderConfig reorder;
  Refill refill = Refill::Warp;
  PrefetchConfig prefetch;  // treelet prefetching into the unit's L1 (off by default)
  AnyHitConfig anyhit;
};

std::string rt_core_config_problem(const RtCoreConfig& config);

struct RtCoreStats {
  uint64_t rays_started = 0, rays_retired = 0;
  uint64_t node_steps = 0, leaf_steps = 0;
  uint64_t instance_steps = 0, top_node_steps = 0;  // two levels: transforms, TLAS node visits
  uint64_t issues = 0;        // issue slots taken: every step, the step that retires a ray too
  uint64_t issue_stalls = 0;  // step starts deferred a cycle by the issue width
  uint64_t fetches = 0, fetch_bytes = 0;    // reads to the L1 (packet mode: after coalescing)
  uint64_t waited_reads = 0;                // reads that waited for data below the L1
  uint64_t late_data = 0, late_cycles = 0;  // data reported after the unit's local cycle
  uint64_t spill_writes = 0, spill_entries = 0, refill_reads = 0, refill_entries = 0;
  uint64_t postponed = 0, refused = 0;  // treelet mode: rays queued, rays a full queue refused
  // Treelet mode: what reading ray states kept in memory (ray_buffer.h) cost.
  ReadCounts state;
  // Two levels: what reading the TLAS (nodes, instance records) and the BLASes cost.
  ReadCounts top, bottom;
  // Any-hit calls, the cycles rays waited for them (from their leaf's tests to the last
  // answer), and what the shader's texel reads cost.
  uint64_t anyhit_calls = 0, anyhit_cycles = 0;
  ReadCounts texture;
  uint64_t warp_steps = 0, active_lanes = 0;  // packet mode
  uint64_t node_warp_steps = 0, distinct_nodes = 0;
  uint64_t packet_lanes = 0;   // lanes of the packets stepped (SIMD efficiency's denominator)
  uint64_t reorders = 0;       // packets regrouped into two narrower ones
  double ray_slot_cycles = 0;  // integral of occupied ray slots over cycles
  Cycle last_cycle = 0;        // the last cycle the unit did anything
};

class RtCore : private ReadClient {
 public:
  // memory: the unit's L1; the unit is the client of every read it makes. footprints: the
  // treelets' (treelet_footprints of traversal's image), required when config.prefetch has a
  // trigger. Throws std::invalid_argument for an impossible config.
  RtCore(uint32_t id, const RtCoreConfig& config, const TraversalUnit& traversal,
         MemoryTarget& memory, const TreeletFootprints* footprints = nullptr);

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
  uint32_t waiting_reads() const { return waiting_reads_; }  // reads whose data is not back
  // The earliest event that reported data scheduled since the last call (kPending: none).
  Cycle take_data_event() {
    Cycle at = data_event_;
    data_event_ = kPending;
    return at;
  }
  uint32_t in_flight() const { return in_flight_; }
  uint32_t slots() const { return uint32_t(slots_.size()); }

  const RtCoreStats& stats() const { return stats_; }
  const TestUnitPool& box() const { return box_; }
  const TestUnitPool& triangle() const { return triangle_; }
  const TestUnitPool& transform() const { return transform_; }
  const TestUnitPool& anyhit_shader() const { return shader_; }
  const PrefetchStats& prefetch_stats() const { return prefetcher_.stats(); }
  const RtCoreConfig& config() const { return config_; }
  uint32_t id() const { return id_; }
  std::string dump() const;  // what every ray is doing, for stall reports
  void account(Cycle now);   // counts slot occupancy up to now

 private:
  // What a slot (packet mode: a packet) waits for, if anything.
  enum class Wait : uint8_t { None, Refill, State, Data };
  struct Next {
    bool live = false;  // an entry that step() will visit (not culled)
    StepKind kind = StepKind::Done;
    uint32_t depth = 0;  // its position in the stack
  };
  Next peek(const TraversalState& state) const;
  // Asks the host's memory (kHostL2) for what the next event's step reads first (its ray's
  // context, control state and stack top): a hint given one event ahead, which changes nothing
  // modelled.
  void prime_next_event() const;
  // The cycle traversal control can start a step asked for at `now`: now, or the first later
  // cycle with a free issue slot (reserved, so the step is scheduled once, not retried).
  Cycle reserve_issue(Cycle now);
  // Whether slot or packet `item` may step at `now`; if not, it is scheduled at its issue cycle.
  bool claim_issue(uint32_t item, Cycle now);
  void fill(Cycle now);
  void install(RayContext* ray, uint32_t slot, Cycle now);
  void retire(uint32_t slot, Cycle now);
  void release(uint32_t slot, Cycle now);
  void on_ray(uint32_t slot, Cycle now);
  void on_packet(uint32_t item, Cycle now);
  // Regroups the packet at `item` and splits it in two; its lanes' next visits in lane_next_.
  void reorder(uint32_t item, StepKind kind, Cycle now);
  bool refills_warps() const {
    return config_.mode == TraversalMode::Packet ||
           (config_.mode == TraversalMode::DepthFirst && config_.refill == Refill::Warp);
  }
  // Packet mode: a packet is the item of its first packet_unit_ lanes.
  uint32_t item_of(uint32_t slot) const {
    return config_.mode == TraversalMode::Packet ? packet_head_[slot / packet_unit_] : slot;
  }
  // A read for the ray: its ready cycle, or kPending (its item then waits for read_done).
  // state: the ray's state from memory, whose cost is also counted in stats_.state.
  Cycle read(RayContext& ray, uint64_t addr, uint32_t bytes, Cycle now, bool state = false);
  void read_done(uint64_t slot, Cycle ready, const ReadCharge& charge) override;
  ReadOrigin origin(uint64_t slot) const override {
    const RayContext* ray = slots_[uint32_t(slot)];
    return {id_, uint32_t(slot), ray ? ray->sequence : ReadOrigin::kUnknown};
  }
  // After an item's reads: wait for the pending ones (true), or go on (false).
  bool wait_reads(uint32_t item, Wait wait, Cycle known_ready);
  Cycle fetch(RayContext& ray, const StepResult& step, Cycle now);
  // Books the tests of a step (packet mode: of a packet step) once its data is there, and
  // schedules the item's next step; returns its cycle.
  Cycle test_step(uint32_t item, Cycle data);
  bool refill(RayContext& ray, const Next& next, Cycle now, Cycle& ready);
  // A resumed ray whose state is in memory reads it before its next step.
  void load_state(RayContext& ray, Cycle now);
  uint32_t treelet_of(const RayContext& ray, const Next& next) const;
  void settle(RayContext& ray, uint32_t kept, uint32_t visited_treelet, Cycle now);
  // What an address holds, for counting a read's cost against it: 1 the top level, 2 the
  // bottom levels (two levels), 3 a texture; 0 anything else.
  uint32_t level_of(uint64_t addr) const;
  // After a leaf's tests done at `tested`: the slot's any-hit calls; returns their last answer.
  Cycle call_anyhit(uint32_t slot, Cycle tested);
  // Issues the step's texel reads; `known` becomes the latest ready cycle known at once.
  void read_texels(RayContext& ray, const StepResult& step, Cycle now, Cycle& known);
  // Counts a step by kind (and level: `after` is the ray's state after it).
  void count_step(StepKind kind, const TraversalState& after);
  void charge_level(uint32_t level, const ReadCharge& charge);
  void check_kind(const StepResult& step, const Next& next) const;
  void prefetch(const std::vector<ByteRange>& ranges, Cycle now);

  uint32_t id_;
  RtCoreConfig config_;
  const TraversalUnit& traversal_;
  // Two levels: the address ranges of the top level [bvh_begin_, top_end_) and the bottom
  // levels [top_end_, bvh_end_).
  uint64_t bvh_begin_, top_end_, bvh_end_;
  bool entry_treelets_;  // keep each stack entry's treelet (treelet mode, first-visit prefetch)
  MemoryTarget& memory_;
  RaySupply* supply_ = nullptr;
  HardwareStack stack_;
  uint32_t state_bytes_;  // treelet mode: one ray's state in the ray buffer
  TestUnitPool box_, triangle_, transform_, shader_;
  TreeletPrefetcher prefetcher_;
  EventQueue events_;
  std::vector<RayContext*> slots_;   // warps * warp_size
  std::vector<uint32_t> warp_live_;  // rays still in each warp (per-ray and packet modes)
  // What traversal control keeps per slot, or per item (slot, or packet in packet mode), in one
  // record per slot: a step touches one host cache line of it, not one per field.
  static constexpr uint32_t kNoTests = ~0u;
  struct SlotState {
    Cycle issue_granted = ~Cycle(0);  // per item: a reserved issue cycle
    Cycle data_ready = 0;             // per item: the latest data of its reads
    uint32_t pending_reads = 0;       // per item: reads not back
    uint32_t tests = kNoTests;        // per slot: the tests of the step waiting for its data
    uint32_t calls = 0;               // per slot: that step's any-hit calls
    Wait wait = Wait::None;           // per item: what it waits for
    StepKind kind = StepKind::Done;   // per item: the kind of the step waiting for its data
    // Per slot: the host address of its ray's stack top after its last step, for a hint.
    const StackEntry* stack_top = nullptr;
  };
  std::vector<SlotState> slot_state_;
  uint32_t waiting_reads_ = 0;
  Cycle data_event_ = kPending;
  std::vector<uint32_t> free_slots_;  // refilled by slot
  std::vector<uint32_t> free_warps_;  // refilled by warp
  std::vector<RayContext*> batch_;
  // Packet mode: packets are aligned runs of packet_unit_ lanes (a warp, or min_width lanes
  // when packets reorder); per run, the item of its packet; per packet item, its lanes.
  uint32_t packet_unit_ = 1;
  std::vector<uint32_t> packet_head_, packet_width_;
  std::vector<Next> lane_next_;  // packet mode scratch
  struct Regroup {
    RayContext* ray;
    bool other_kind;
    uint32_t node, lane;
  };
  std::vector<Regroup> regroup_;
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
