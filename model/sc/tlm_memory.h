// The memory hierarchy's ends as modules: an RT unit's own cache levels, which send their
// misses, writes and evictions to the shared levels (model/sc/shared_levels_module.h) by
// function call, and the simple DRAM as a loosely-timed TLM-2.0 target (which the shared levels
// call in simulated-time order; another loosely-timed TLM memory model can be bound in its
// place).
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
#include "model/mem/hierarchy.h"
#include "model/sc/clock.h"

namespace rtsim {

class SharedLevelsModule;

// An RT unit's own levels (scope "unit" in model/mem/hierarchy.h), first to last. The unit
// reads the first by a direct call (they are the unit's own); each level's misses, writes and
// evictions go to the next by call, and the last one's to the shared levels it is connected to
// (connect), also by call, as request records those serve in time order; they answer each read
// through its client's read_done and then call on_response, so the owner can wake up.
class UnitMemory : public sc_core::sc_module, private MemoryTarget {
 public:
  // levels: the machine's hierarchy; the unit's own are its first levels of scope unit.
  UnitMemory(sc_core::sc_module_name name, const std::vector<MemoryLevelConfig>& levels,
             std::function<void()> on_response = {});
  // A unit with one level of `config` (tests).
  UnitMemory(sc_core::sc_module_name name, const CacheConfig& config,
             std::function<void()> on_response = {});
  // Before the simulation starts: the shared levels below, which this is unit `unit` of.
  void connect(SharedLevelsModule& shared, uint32_t unit = 0);
  Cache& cache() { return *caches_.front(); }  // the first level: what the unit reads
  const Cache& cache() const { return *caches_.front(); }
  uint32_t levels() const { return uint32_t(caches_.size()); }
  const Cache& level(uint32_t i) const { return *caches_[i]; }
  Cache& level(uint32_t i) { return *caches_[i]; }

 private:
  Cycle read(uint64_t addr, uint32_t bytes, Cycle at, ReadClient* client, uint64_t token,
             ReadCharge& charge) override;
  void write(uint64_t addr, uint32_t bytes, Cycle at) override;
  void fill(uint64_t addr, uint32_t bytes, Cycle at) override;
  void before_end_of_elaboration() override;  // unconnected: a wiring error

  std::function<void()> on_response_;
  SharedLevelsModule* shared_ = nullptr;
  uint32_t instance_ = 0, port_ = 0;
  std::vector<std::unique_ptr<Cache>> caches_;
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
