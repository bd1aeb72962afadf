#include "model/sc/tlm_memory.h"

#include <stdexcept>
#include <string>

namespace rtsim {
namespace {

void check(const tlm::tlm_generic_payload& trans) {
  if (trans.is_response_error())
    throw std::runtime_error("memory access at " + std::to_string(trans.get_address()) +
                             " failed: " + trans.get_response_string());
}

}  // namespace

L1Module::L1Module(sc_core::sc_module_name name, const CacheConfig& config, const Clock& clock,
                   std::function<void()> on_response)
    : sc_module(name),
      out("out"),
      clock_(clock),
      on_response_(std::move(on_response)),
      cache_(config, this, CacheRole::L1) {
  out.register_nb_transport_bw(this, &L1Module::nb_transport_bw);
}

L1Module::Transaction& L1Module::take() {
  if (free_.empty()) {
    pool_.push_back(std::make_unique<Transaction>());
    Transaction& t = *pool_.back();
    t.charge = new ReadChargeExtension;
    t.set_extension(t.charge);  // owned and freed by the payload
    t.set_byte_enable_ptr(nullptr);
    t.set_dmi_allowed(false);
    return t;
  }
  Transaction* t = free_.back();
  free_.pop_back();
  return *t;
}

bool L1Module::send(Transaction& t, tlm::tlm_command command, uint64_t addr, uint32_t bytes,
                    Cycle at, sc_core::sc_time& delay) {
  if (scratch_.size() < bytes) scratch_.resize(bytes);
  t.set_command(command);
  t.set_address(addr);
  t.set_data_ptr(scratch_.data());
  t.set_data_length(bytes);
  t.set_streaming_width(bytes);
  t.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
  t.charge->charge = {};
  tlm::tlm_phase phase = tlm::BEGIN_REQ;
  delay = clock_.delay_to(at);
  tlm::tlm_sync_enum status = out->nb_transport_fw(t, phase, delay);
  bool done = status == tlm::TLM_COMPLETED || phase == tlm::BEGIN_RESP;
  if (done) check(t);
  return done;
}

Cycle L1Module::read(uint64_t addr, uint32_t bytes, Cycle at, ReadClient* client, uint64_t token,
                     ReadCharge& charge) {
  Transaction& t = take();
  t.client = client;
  t.token = token;
  sc_core::sc_time delay;
  if (!send(t, tlm::TLM_READ_COMMAND, addr, bytes, at, delay)) return kPending;
  charge += t.charge->charge;
  give_back(t);
  return clock_.cycles(sim_now() + delay);
}

void L1Module::write(uint64_t addr, uint32_t bytes, Cycle at) {
  Transaction& t = take();
  t.client = nullptr;
  sc_core::sc_time delay;
  if (send(t, tlm::TLM_WRITE_COMMAND, addr, bytes, at, delay)) give_back(t);
}

tlm::tlm_sync_enum L1Module::nb_transport_bw(tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase,
                                             sc_core::sc_time& delay) {
  if (phase != tlm::BEGIN_RESP) return tlm::TLM_ACCEPTED;
  check(trans);
  auto& t = static_cast<Transaction&>(trans);
  Cycle ready = clock_.cycles(sim_now() + delay);
  ReadClient* client = t.client;
  uint64_t token = t.token;
  ReadCharge charge = t.charge->charge;
  give_back(t);
  if (client) {
    client->read_done(token, ready, charge);
    if (on_response_) on_response_();
  }
  return tlm::TLM_COMPLETED;
}

DramModule::DramModule(sc_core::sc_module_name name, const DramConfig& config, const Clock& clock)
    : sc_module(name), in("in"), clock_(clock), dram_(config) {
  in.register_b_transport(this, &DramModule::b_transport);
}

void DramModule::b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) {
  bool write = trans.get_command() == tlm::TLM_WRITE_COMMAND;
  if (!write && trans.get_command() != tlm::TLM_READ_COMMAND) {
    trans.set_response_status(tlm::TLM_COMMAND_ERROR_RESPONSE);
    return;
  }
  sc_core::sc_time stamp = sim_now();
  Cycle now = clock_.cycles(stamp + delay);
  Cycle ready = now;
  if (write)
    dram_.write(trans.get_address(), trans.get_data_length(), now);  // the writer does not wait
  else
    ready = dram_.read(trans.get_address(), trans.get_data_length(), now);
  delay = clock_.time(ready) - stamp;
  trans.set_response_status(tlm::TLM_OK_RESPONSE);
}

}  // namespace rtsim
