// A third-party style approximately-timed memory, built as DRAMSys-class models are: a request
// is accepted at once (END_REQ) and answered BEGIN_RESP through a payload event queue when its
// data is there, `latency` after the request's date, with no lead. Writes complete at once.
#pragma once

#include <systemc>
#include <tlm>
#include <tlm_utils/peq_with_get.h>
#include <tlm_utils/simple_target_socket.h>

namespace rtsim::test {

struct TimedMemory : sc_core::sc_module {
  tlm_utils::simple_target_socket<TimedMemory> in{"in"};
  tlm_utils::peq_with_get<tlm::tlm_generic_payload> responses{"responses"};
  sc_core::sc_time latency;
  int reads = 0;
  SC_HAS_PROCESS(TimedMemory);
  TimedMemory(sc_core::sc_module_name name, sc_core::sc_time latency)
      : sc_module(name), latency(latency) {
    in.register_nb_transport_fw(this, &TimedMemory::nb_transport_fw);
    SC_METHOD(respond);
    sensitive << responses.get_event();
    dont_initialize();
  }
  tlm::tlm_sync_enum nb_transport_fw(tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase,
                                     sc_core::sc_time& delay) {
    if (phase != tlm::BEGIN_REQ) return tlm::TLM_COMPLETED;
    trans.set_response_status(tlm::TLM_OK_RESPONSE);
    if (trans.is_write()) return tlm::TLM_COMPLETED;
    ++reads;
    responses.notify(trans, delay + latency);
    phase = tlm::END_REQ;
    return tlm::TLM_UPDATED;
  }
  void respond() {
    while (tlm::tlm_generic_payload* trans = responses.get_next_transaction()) {
      tlm::tlm_phase phase = tlm::BEGIN_RESP;
      sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
      in->nb_transport_bw(*trans, phase, delay);
    }
  }
};

}  // namespace rtsim::test
