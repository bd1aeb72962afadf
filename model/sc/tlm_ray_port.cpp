#include "model/sc/tlm_ray_port.h"

#include <stdexcept>
#include <string>

namespace rtsim {

TlmRayPort::TlmRayPort(Transport transport, const Clock& clock)
    : transport_(std::move(transport)), clock_(clock) {}

Cycle TlmRayPort::send(tlm::tlm_command command, uint64_t addr, uint32_t bytes, Cycle now) {
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

Cycle TlmRayPort::read(uint64_t addr, uint32_t bytes, Cycle now) {
  return send(tlm::TLM_READ_COMMAND, addr, bytes, now);
}

void TlmRayPort::write(uint64_t addr, uint32_t bytes, Cycle now) {
  send(tlm::TLM_WRITE_COMMAND, addr, bytes, now);
}

}  // namespace rtsim
