// An RT unit's port into its L1 as a RayMemory: reads and posted writes sent as TLM-2.0
// base-protocol transactions (blocking transport, loosely timed) by a TlmInitiator
// (model/sc/tlm_memory.h). The request time is the unit's local cycle, which may run ahead of
// sc_time_stamp() by up to the quantum.
#pragma once

#include "model/sc/tlm_memory.h"
#include "model/sched/ray_supply.h"

namespace rtsim {

class TlmRayPort : public RayMemory {
 public:
  using Transport = TlmInitiator::Transport;
  TlmRayPort(Transport transport, const Clock& clock) : initiator_(std::move(transport), clock) {}
  Cycle read(uint64_t addr, uint32_t bytes, Cycle now) override {
    return initiator_.send(tlm::TLM_READ_COMMAND, addr, bytes, now);
  }
  void write(uint64_t addr, uint32_t bytes, Cycle now) override {
    initiator_.send(tlm::TLM_WRITE_COMMAND, addr, bytes, now);
  }

 private:
  TlmInitiator initiator_;
};

}  // namespace rtsim
