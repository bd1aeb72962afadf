// Everything the hardware holds for one ray in flight: the ray, its traversal state (the very
// state the functional traversal steps), where its hardware stack stands, and what it cost so
// far. Contexts come from a fixed pool sized by the rays the hardware can hold, so memory is
// bounded by rays in flight, never by the length of the stream.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "model/mem/memory_level.h"
#include "model/sched/stack_residency.h"
#include "model/units/traversal.h"
#include "traces/ray.h"

namespace rtsim {

// What one ray cost, accumulated step by step and read when it retires.
struct RayCost {
  RayReads reads;              // block accesses and hits at each cache level, DRAM bytes
  uint32_t stack_spills = 0;   // entries written out of the hardware stack
  uint32_t stack_refills = 0;  // entries read back
  uint32_t postponed = 0;      // times it waited in a treelet queue
  uint64_t anyhit_cycles = 0;  // cycles waiting for any-hit calls (rt_core.h)
};

// What a unit touches at every step comes first, then the traversal state (its own hot part
// first), so a step touches few host cache lines of the thousands of contexts in flight.
struct alignas(64) RayContext {
  Cycle ready = 0;               // earliest cycle of its next step (arrival, queue exit)
  uint32_t unit = 0, slot = 0;   // where it runs now
  StackResidency residency;      // its stack's entries on chip and spilled (hardware_stack.h)
  uint32_t stack_region = 0;     // whose spill region holds its spilled entries (hardware_stack.h)
  bool state_in_memory = false;  // queued with its state in memory (model/sched/ray_buffer.h)
  bool begun = false;            // ray setup done (TraversalUnit::begin)
  RayCost cost;
  TraversalState state;
  Ray ray;
  uint64_t sequence = 0;     // position in the ray stream
  uint32_t id = 0;           // index in the pool; in treelet mode names its stack spill region
  uint32_t shader_warp = 0;  // the SM's warp slot that traced it (shader_core.h)
  Cycle dispatched = 0;      // cycle the dispatcher handed the ray out
  Cycle handed = 0;          // cycle it was handed toward a unit: dispatch, or leaving the sorter
  // Treelet mode: the treelet being traversed, the treelet of each stack entry, and the next
  // ray in the same queue.
  uint32_t treelet = 0;
  std::vector<uint32_t> entry_treelet;
  RayContext* next_in_queue = nullptr;
};

// A first-in first-out queue of contexts linked through next_in_queue (treelet queues, sorting
// bins); `length` is kept by the owner, which reports it to its policy.
struct RayFifo {
  RayContext* head = nullptr;
  RayContext* tail = nullptr;
  uint32_t length = 0;

  void push(RayContext* ray) {
    ray->next_in_queue = nullptr;
    (tail ? tail->next_in_queue : head) = ray;
    tail = ray;
  }
  RayContext* pop() {
    RayContext* ray = head;
    head = ray->next_in_queue;
    ray->next_in_queue = nullptr;
    if (!head) tail = nullptr;
    return ray;
  }
};

// A fixed set of contexts handed out and given back, last freed first (deterministic).
class RayContextPool {
 public:
  explicit RayContextPool(uint32_t capacity);
  RayContext* acquire();  // nullptr when every context is in use
  void release(RayContext* context);
  uint32_t capacity() const { return uint32_t(contexts_.size()); }
  uint32_t in_use() const { return capacity() - uint32_t(free_.size()); }

 private:
  std::vector<std::unique_ptr<RayContext>> contexts_;
  std::vector<RayContext*> free_;
};

}  // namespace rtsim
