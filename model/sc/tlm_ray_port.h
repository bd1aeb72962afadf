// An RT unit's port into its L1 as a RayMemory: reads and posted writes sent as TLM-2.0
// base-protocol transactions (blocking transport, loosely timed). The request time is the
// unit's local cycle, which may run ahead of sc_time_stamp() by up to the quantum (temporal
// decoupling: the delay argument carries the offset). One payload is reused for every call.
#pragma once

#include <functional>
#include <vector>

#include <systemc>
#include <tlm>

#include "model/sc/clock.h"
#include "model/sched/ray_supply.h"

namespace rtsim {

class TlmRayPort : public RayMemory {
public:
  using Transport = std::function<void(tlm::tlm_generic_payload&, sc_core::sc_time&)>;
  TlmRayPort(Transport transport, const Clock& clock);
  Cycle read(uint64_t addr, uint32_t bytes, Cycle now) override;
  void write(uint64_t addr, uint32_t bytes, Cycle now) override;

private:
  Cycle send(tlm::tlm_command command, uint64_t addr, uint32_t bytes, Cycle now);

  Transport transport_;
  Clock clock_;
  tlm::tlm_generic_payload trans_;
  std::vector<unsigned char> scratch_;
};

}  // namespace rtsim
