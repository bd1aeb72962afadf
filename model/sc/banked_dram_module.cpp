#include "model/sc/banked_dram_module.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rtsim {

BankedDramModule::BankedDramModule(sc_core::sc_module_name name, const BankedDramConfig& config,
                                   const Clock& clock, double core_ghz)
    : sc_module(name), in("in"), clock_(clock), controller_(config, core_ghz) {
  in.register_nb_transport_fw(this, &BankedDramModule::nb_transport_fw);
  SC_METHOD(decide);
  sensitive << wake_;
  dont_initialize();
}

void BankedDramModule::set_response_lead(uint32_t lead) {
  slack_ = max_response_lead() - std::min(lead, max_response_lead());
}

uint32_t BankedDramModule::max_response_lead() const {
  // A read's data comes tCL and a burst after its RD, decided at most a cycle after its clock.
  const BankedDramConfig& c = controller_.config();
  Cycle data = controller_.to_core(c.timing.tCL + c.burst_clocks());
  return uint32_t(c.controller_latency + (data > 2 ? data - 2 : 0));
}

tlm::tlm_sync_enum BankedDramModule::nb_transport_fw(tlm::tlm_generic_payload& trans,
                                                     tlm::tlm_phase& phase,
                                                     sc_core::sc_time& delay) {
  if (phase != tlm::BEGIN_REQ) return tlm::TLM_COMPLETED;  // END_RESP
  bool write = trans.get_command() == tlm::TLM_WRITE_COMMAND;
  if (!write && trans.get_command() != tlm::TLM_READ_COMMAND) {
    trans.set_response_status(tlm::TLM_COMMAND_ERROR_RESPONSE);
    return tlm::TLM_COMPLETED;
  }
  Cycle at = clock_.cycles(sim_now() + delay);
  enqueue(reinterpret_cast<uint64_t>(&trans), trans.get_address(), trans.get_data_length(), write,
          at);
  trans.set_response_status(tlm::TLM_OK_RESPONSE);
  if (write) return tlm::TLM_COMPLETED;
  phase = tlm::END_REQ;
  return tlm::TLM_UPDATED;
}

Cycle BankedDramModule::read(uint64_t addr, uint32_t bytes, Cycle at, ReadClient* client,
                             uint64_t token, ReadCharge&) {
  if (client_ && client_ != client)
    throw std::logic_error(std::string(name()) + ": reads by call from a second requester");
  client_ = client;
  enqueue(token, addr, bytes, false, at);
  return kPending;
}

void BankedDramModule::write(uint64_t addr, uint32_t bytes, Cycle at) {
  enqueue(0, addr, bytes, true, at);
}

void BankedDramModule::enqueue(uint64_t token, uint64_t addr, uint32_t bytes, bool write,
                               Cycle at) {
  Cycle next = controller_.enqueue(token, addr, bytes, write, at);
  if (!deciding_) arm_at(next);
}

void BankedDramModule::arm_at(Cycle next) {
  if (next == kPending || next + 1 + slack_ >= armed_) return;
  armed_ = next + 1 + slack_;
  wake_.notify(clock_.delay_to(armed_));
}

void BankedDramModule::decide() {
  sc_core::sc_time now = sim_now();
  Cycle cycle = clock_.cycles(now);
  armed_ = kPending;
  deciding_ = true;
  done_.clear();
  controller_.advance(cycle - 1, done_);
  for (const DramReadDone& d : done_) {
    if (client_) {
      client_->read_done(d.id, std::max(d.ready, cycle), {});
      continue;
    }
    auto& trans = *reinterpret_cast<tlm::tlm_generic_payload*>(d.id);
    tlm::tlm_phase phase = tlm::BEGIN_RESP;
    sc_core::sc_time delay = clock_.time(std::max(d.ready, cycle)) - now;
    in->nb_transport_bw(trans, phase, delay);
  }
  deciding_ = false;
  arm();
}

}  // namespace rtsim
