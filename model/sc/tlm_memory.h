// TLM-2.0 wrappers of the memory hierarchy (model/mem): caches and DRAM as sc_modules joined
// by sockets, so that another loosely-timed TLM memory model can be bound where the DRAM is.
// Protocol: the base protocol's blocking transport, loosely timed. A read transaction starts at
// sc_time_stamp() + delay; the target adds to delay the time until its data is ready. Only the
// address and length matter: the functional model reads BVH data itself, so targets do not
// fill the data buffer. No module has a thread: a transaction is one function call chain,
// and callers sleep until the returned time.
// Writes (stack spills) are posted: caches pass them below without allocating (write-around),
// and the DRAM charges their bytes to its bus like reads.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/multi_passthrough_target_socket.h>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>

#include "model/mem/cache.h"
#include "model/mem/dram.h"
#include "model/sc/clock.h"

namespace rtsim {

// Sends reads and writes as TLM transactions through `transport` (a socket's b_transport,
// looked up at call time because sockets bind after construction). The request time is the
// caller's cycle, which may run ahead of sc_time_stamp() (temporal decoupling: the delay
// argument carries the offset). Returns the cycle the target is done.
class TlmInitiator {
 public:
  using Transport = std::function<void(tlm::tlm_generic_payload&, sc_core::sc_time&)>;
  TlmInitiator(Transport transport, const Clock& clock)
      : transport_(std::move(transport)), clock_(clock) {}
  Cycle send(tlm::tlm_command command, uint64_t addr, uint32_t bytes, Cycle now);

 private:
  Transport transport_;
  Clock clock_;
  tlm::tlm_generic_payload trans_;  // reused: one transaction in flight in the call chain
  std::vector<unsigned char> scratch_;
};

// A MemoryLevel whose reads go out as TLM transactions.
class TlmReadPort : public MemoryLevel {
 public:
  TlmReadPort(TlmInitiator::Transport transport, const Clock& clock)
      : initiator_(std::move(transport), clock) {}
  Cycle read(uint64_t addr, uint32_t bytes, Cycle now) override {
    return initiator_.send(tlm::TLM_READ_COMMAND, addr, bytes, now);
  }

 private:
  TlmInitiator initiator_;
};

// A cache level: any number of initiators bind to `in`; misses go out through `out`.
class CacheModule : public sc_core::sc_module {
 public:
  tlm_utils::multi_passthrough_target_socket<CacheModule> in;
  tlm_utils::simple_initiator_socket<CacheModule> out;

  CacheModule(sc_core::sc_module_name name, const CacheConfig& config, const Clock& clock);
  const Cache& cache() const { return cache_; }
  Cache& cache() { return cache_; }
  // The cache level itself, for the initiator that owns this cache (an RT unit and its L1):
  // reads without a transaction, the timing analogue of a TLM DMI pointer. Same answers as
  // the `in` socket; misses still go out through `out`.
  MemoryLevel& direct() { return cache_; }
  uint64_t write_bytes() const { return write_bytes_; }  // bytes written around this level

 private:
  void b_transport(int port, tlm::tlm_generic_payload& trans, sc_core::sc_time& delay);

  Clock clock_;
  TlmReadPort below_;
  Cache cache_;
  uint64_t write_bytes_ = 0;
};

class DramModule : public sc_core::sc_module {
 public:
  tlm_utils::simple_target_socket<DramModule> in;

  DramModule(sc_core::sc_module_name name, const DramConfig& config, const Clock& clock);
  const Dram& dram() const { return dram_; }
  uint64_t write_bytes() const { return write_bytes_; }  // of dram().stats().bytes

 private:
  void b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay);

  Clock clock_;
  Dram dram_;
  uint64_t write_bytes_ = 0;
};

}  // namespace rtsim
