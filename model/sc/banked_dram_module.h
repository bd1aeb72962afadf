// The banked DRAM (model/mem/dram_controller.h) below the shared levels: connected by call (a
// MemoryTarget: the fast path, SharedLevelsModule::connect_memory), or as a TLM-2.0 target
// speaking the approximately-timed base protocol, bound where the simple DRAM's loosely-timed
// target binds.
// By call, a request is queued at once; a read returns kPending and its data cycle is reported
// to its client's read_done when the controller has scheduled it, under the timing rules below.
// Protocol. A read or write comes as BEGIN_REQ through nb_transport_fw, dated by its delay;
// the target queues it and answers END_REQ at once (TLM_UPDATED; its queues back-pressure
// inside, so END_REQ is never held back). A write is then complete (posted; TLM_COMPLETED). A
// read is answered BEGIN_RESP through nb_transport_bw once its data's cycle is known, with a
// delay saying when the data is there; the initiator completes it (TLM_COMPLETED or END_RESP).
// Timing. One SC_METHOD, woken only when the controller has a decision to take. It takes the
// decisions of cycle c no earlier than simulated time c + 1, when every request dated c has
// arrived (the L2 sends each request no later than its own cycle), and no later than c + 1 +
// slack, so BEGIN_RESP comes at least response_lead() cycles before the data: the L2 uses that to
// bound how far ahead it serves. The slack (0 unless set_response_lead lowers the lead) lets one
// wake-up take the decisions of many cycles: the controller decides the same (a request joins its
// queue at its arrival, however early it was enqueued), only the L2 may see two events of one
// cycle in another order.
#pragma once

#include <algorithm>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_target_socket.h>

#include "model/mem/dram_controller.h"
#include "model/sc/clock.h"

namespace rtsim {

class BankedDramModule : public sc_core::sc_module, public MemoryTarget {
 public:
  tlm_utils::simple_target_socket_optional<BankedDramModule> in;  // unbound: used by call

  SC_HAS_PROCESS(BankedDramModule);
  // Throws std::invalid_argument for an impossible config.
  BankedDramModule(sc_core::sc_module_name name, const BankedDramConfig& config, const Clock& clock,
                   double core_ghz);
  const DramController& controller() const { return controller_; }
  // Cycles by which every BEGIN_RESP precedes its data, at the least.
  uint32_t response_lead() const { return max_response_lead() - slack_; }
  // Before the simulation: BEGIN_RESP need precede the data by only `lead` cycles (at most
  // max_response_lead()), so decisions may wait the difference.
  void set_response_lead(uint32_t lead);
  uint32_t max_response_lead() const;
  Cycle next_event() const { return controller_.next_event(); }
  // The cycle decide() is woken for (kPending: none): a decision of cycle c is taken up to
  // 1 + slack cycles later, or at once (in a delta cycle) when a request comes for a cycle
  // already past. So this, not next_event(), says when the DRAM acts next: what the stall
  // watchdog must wait for.
  Cycle next_wake() const {
    return armed_ == kPending ? kPending : std::max(armed_, clock_.cycles(sim_now()));
  }
  // By call (MemoryTarget), in non-decreasing `at`; a module takes its requests by call or
  // through `in`, not both, and by call from one requester: every read names the same client.
  // Throws std::logic_error for a second client.
  Cycle read(uint64_t addr, uint32_t bytes, Cycle at, ReadClient* client, uint64_t token,
             ReadCharge& charge) override;
  void write(uint64_t addr, uint32_t bytes, Cycle at) override;

 private:
  tlm::tlm_sync_enum nb_transport_fw(tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase,
                                     sc_core::sc_time& delay);
  void decide();
  void arm() { arm_at(controller_.next_event()); }  // wakes decide() for the next decision
  // Wakes decide() for a decision from core cycle `next` on, if none is armed before. A request
  // (outside decide(), which arms once it is done) arms only for its own channels: the others'
  // decisions are armed for already.
  void arm_at(Cycle next);

  Clock clock_;
  DramController controller_;
  sc_core::sc_event wake_;
  uint32_t slack_ = 0;      // cycles a decision may be taken late
  Cycle armed_ = kPending;  // the cycle wake_ is notified for
  bool deciding_ = false;   // in decide()
  std::vector<DramReadDone> done_;
  void enqueue(uint64_t token, uint64_t addr, uint32_t bytes, bool write, Cycle at);

  ReadClient* client_ = nullptr;  // by call: whom reads answer (null: through `in`)
};

}  // namespace rtsim
