// The memory hierarchy's ends as modules: an RT unit's L1, which sends its misses and writes to
// the shared L2 (model/sc/shared_cache_module.h) by function call, and the simple DRAM as a
// loosely-timed TLM-2.0 target (which the L2 calls in simulated-time order; another
// loosely-timed TLM memory model can be bound in its place).
// Only addresses and lengths matter: the functional model reads BVH data itself, so targets do
// not fill data buffers. No module has a thread: a request is a function call chain.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_target_socket.h>

#include "model/mem/cache.h"
#include "model/mem/dram.h"
#include "model/sc/clock.h"

namespace rtsim {

class SharedCacheModule;

// An RT unit's L1. The unit reads it by a direct call (it is the unit's own); its misses and
// posted writes go to the shared L2 it is connected to (connect), also by call, as request
// records the L2 serves in time order; the L2 answers each read through its client's
// read_done and then calls on_response, so the owner can wake up.
class L1Module : public sc_core::sc_module, private MemoryTarget {
 public:
  L1Module(sc_core::sc_module_name name, const CacheConfig& config,
           std::function<void()> on_response = {});
  // Before the simulation starts: the L2 below this L1 (one of its requester ports).
  void connect(SharedCacheModule& l2);
  Cache& cache() { return cache_; }
  const Cache& cache() const { return cache_; }

 private:
  Cycle read(uint64_t addr, uint32_t bytes, Cycle at, ReadClient* client, uint64_t token,
             ReadCharge& charge) override;
  void write(uint64_t addr, uint32_t bytes, Cycle at) override;
  void before_end_of_elaboration() override;  // an unconnected L1 is a wiring error

  std::function<void()> on_response_;
  SharedCacheModule* l2_ = nullptr;
  uint32_t port_ = 0;
  Cache cache_;
};

class DramModule : public sc_core::sc_module {
 public:
  tlm_utils::simple_target_socket<DramModule> in;

  DramModule(sc_core::sc_module_name name, const DramConfig& config, const Clock& clock);
  const Dram& dram() const { return dram_; }

 private:
  void b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay);

  Clock clock_;
  Dram dram_;
};

}  // namespace rtsim
