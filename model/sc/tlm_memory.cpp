#include "model/sc/tlm_memory.h"

#include <stdexcept>
#include <string>

#include "model/sc/shared_cache_module.h"

namespace rtsim {

L1Module::L1Module(sc_core::sc_module_name name, const CacheConfig& config,
                   std::function<void()> on_response)
    : sc_module(name), on_response_(std::move(on_response)), cache_(config, this, CacheRole::L1) {}

void L1Module::connect(SharedCacheModule& l2) {
  l2_ = &l2;
  port_ = l2.connect(on_response_ ? on_response_ : std::function<void()>([] {}));
}

void L1Module::before_end_of_elaboration() {
  if (!l2_) throw std::logic_error(std::string(name()) + ": not connected to an L2");
}

Cycle L1Module::read(uint64_t addr, uint32_t bytes, Cycle at, ReadClient* client, uint64_t token,
                     ReadCharge&) {
  l2_->read_request(port_, addr, bytes, at, client, token);
  return kPending;
}

void L1Module::write(uint64_t addr, uint32_t bytes, Cycle at) {
  l2_->write_request(port_, addr, bytes, at);
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
