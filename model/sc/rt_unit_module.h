// An RT unit as an sc_module: traversal control and test units (model/sched/rt_core.h) with
// its own L1 (child module "l1", so its stats are "rtN.l1.*"). The unit reaches its L1 through
// a TLM-2.0 initiator socket; the L1's `out` socket binds to the shared L2. Rays come from the
// supply port (dispatcher or treelet queues).
// With direct_l1 the unit reads its own L1 by a direct call instead of a transaction (like a
// TLM DMI pointer: same timing, less host time); writes and everything below the L1 stay TLM.
// One SC_METHOD, no thread per ray: it wakes at the cycle of the unit's next event (or when
// the supply announces work), handles every event before now + quantum (TLM temporal
// decoupling: requests carry the unit's local time as their delay), and sleeps again. A unit
// whose rays all wait on memory sleeps until the cycle the first data arrives.
#pragma once

#include <tlm_utils/simple_initiator_socket.h>
#include <systemc>

#include "model/sc/ray_supply_if.h"
#include "model/sc/tlm_memory.h"
#include "model/sc/tlm_ray_port.h"
#include "model/sched/rt_core.h"

namespace rtsim {

class RtUnitModule : public sc_core::sc_module {
public:
  tlm_utils::simple_initiator_socket<RtUnitModule> mem;  // bound to l1.in
  sc_core::sc_port<RaySupplyIf> supply;
  CacheModule l1;

  SC_HAS_PROCESS(RtUnitModule);
  // l2_stats: the shared L2's counters, to charge each ray its L2 accesses and DRAM bytes.
  RtUnitModule(sc_core::sc_module_name name, uint32_t id, const RtCoreConfig& config,
               const CacheConfig& l1_config, const TraversalUnit& traversal, const Clock& clock,
               uint32_t quantum_cycles, bool direct_l1, const CacheStats* l2_stats,
               SimControl& control);

  const RtCore& core() const { return core_; }
  RtCore& core() { return core_; }

private:
  // Reads straight from the L1 level, writes through the socket.
  class DirectL1 : public RayMemory {
  public:
    DirectL1(MemoryLevel& l1, TlmRayPort& port) : l1_(l1), port_(port) {}
    Cycle read(uint64_t addr, uint32_t bytes, Cycle now) override {
      return l1_.read(addr, bytes, now);
    }
    void write(uint64_t addr, uint32_t bytes, Cycle now) override { port_.write(addr, bytes, now); }

  private:
    MemoryLevel& l1_;
    TlmRayPort& port_;
  };

  void start_of_simulation() override;
  void run();

  Clock clock_;
  uint32_t quantum_;
  SimControl& control_;
  TlmRayPort port_;
  DirectL1 direct_;
  RtCore core_;
};

}  // namespace rtsim
