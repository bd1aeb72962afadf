#include "model/sc/tlm_memory.h"

#include <stdexcept>

namespace rtsim {
namespace {

// Serves a read with `level` and advances delay to the cycle its data is ready.
void serve(MemoryLevel& level, const Clock& clock, tlm::tlm_generic_payload& trans,
           sc_core::sc_time& delay) {
  if (trans.get_command() != tlm::TLM_READ_COMMAND) {
    trans.set_response_status(tlm::TLM_COMMAND_ERROR_RESPONSE);
    return;
  }
  sc_core::sc_time stamp = sc_core::sc_time_stamp();
  Cycle ready =
      level.read(trans.get_address(), trans.get_data_length(), clock.cycles(stamp + delay));
  delay = clock.time(ready) - stamp;
  trans.set_response_status(tlm::TLM_OK_RESPONSE);
}

}  // namespace

Cycle TlmInitiator::send(tlm::tlm_command command, uint64_t addr, uint32_t bytes, Cycle now) {
  if (scratch_.size() < bytes) scratch_.resize(bytes);
  trans_.set_command(command);
  trans_.set_address(addr);
  trans_.set_data_ptr(scratch_.data());
  trans_.set_data_length(bytes);
  trans_.set_streaming_width(bytes);
  trans_.set_byte_enable_ptr(nullptr);
  trans_.set_dmi_allowed(false);
  trans_.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
  sc_core::sc_time stamp = sc_core::sc_time_stamp();
  sc_core::sc_time delay = clock_.time(now) - stamp;
  transport_(trans_, delay);
  if (trans_.is_response_error())
    throw std::runtime_error("memory access at " + std::to_string(addr) +
                             " failed: " + trans_.get_response_string());
  return clock_.cycles(stamp + delay);
}

CacheModule::CacheModule(sc_core::sc_module_name name, const CacheConfig& config,
                         const Clock& clock)
    : sc_module(name),
      in("in"),
      out("out"),
      clock_(clock),
      below_([this](auto& trans, auto& delay) { out->b_transport(trans, delay); }, clock),
      cache_(config, &below_) {
  in.register_b_transport(this, &CacheModule::b_transport);
}

void CacheModule::b_transport(int, tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) {
  if (trans.get_command() == tlm::TLM_WRITE_COMMAND) {
    write_bytes_ += trans.get_data_length();
    out->b_transport(trans, delay);  // write-around: no allocation, no tag check
    return;
  }
  serve(cache_, clock_, trans, delay);
}

DramModule::DramModule(sc_core::sc_module_name name, const DramConfig& config, const Clock& clock)
    : sc_module(name), in("in"), clock_(clock), dram_(config) {
  in.register_b_transport(this, &DramModule::b_transport);
}

void DramModule::b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) {
  if (trans.get_command() == tlm::TLM_WRITE_COMMAND) {
    // A write takes the bus for its bytes like a read; the writer does not wait for it.
    write_bytes_ += trans.get_data_length();
    sc_core::sc_time stamp = sc_core::sc_time_stamp();
    Cycle ready =
        dram_.read(trans.get_address(), trans.get_data_length(), clock_.cycles(stamp + delay));
    delay = clock_.time(ready) - stamp;
    trans.set_response_status(tlm::TLM_OK_RESPONSE);
    return;
  }
  serve(dram_, clock_, trans, delay);
}

}  // namespace rtsim
