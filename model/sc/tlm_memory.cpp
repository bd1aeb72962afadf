#include "model/sc/tlm_memory.h"

#include <stdexcept>
#include <string>

#include "model/sc/shared_levels_module.h"

namespace rtsim {

namespace {

// A unit's one level in front of a shared one (whose config is not used here).
std::vector<MemoryLevelConfig> one_level(const CacheConfig& config) {
  MemoryLevelConfig own, shared;
  own.name = "l1";
  own.cache = config;
  shared.name = "l2";
  shared.scope = LevelScope::Shared;
  return {own, shared};
}

}  // namespace

UnitMemory::UnitMemory(sc_core::sc_module_name name, const std::vector<MemoryLevelConfig>& levels,
                       std::function<void()> on_response)
    : sc_module(name), on_response_(std::move(on_response)) {
  uint32_t own = own_levels(levels);
  caches_.resize(own);
  for (uint32_t i = own; i-- > 0;) {
    MemoryTarget* below = i + 1 < own ? caches_[i + 1].get() : static_cast<MemoryTarget*>(this);
    caches_[i] = std::make_unique<Cache>(levels[i].cache, below, cache_place(levels, i));
  }
}

UnitMemory::UnitMemory(sc_core::sc_module_name name, const CacheConfig& config,
                       std::function<void()> on_response)
    : UnitMemory(name, one_level(config), std::move(on_response)) {}

void UnitMemory::connect(SharedLevelsModule& shared, uint32_t unit) {
  shared_ = &shared;
  instance_ = shared.entry(unit);
  port_ = shared.connect(unit, on_response_ ? on_response_ : std::function<void()>([] {}));
}

void UnitMemory::before_end_of_elaboration() {
  if (!shared_) throw std::logic_error(std::string(name()) + ": not connected to shared levels");
}

Cycle UnitMemory::read(uint64_t addr, uint32_t bytes, Cycle at, ReadClient* client, uint64_t token,
                       ReadCharge&) {
  shared_->read_request(instance_, port_, addr, bytes, at, client, token);
  return kPending;
}

void UnitMemory::write(uint64_t addr, uint32_t bytes, Cycle at) {
  shared_->write_request(instance_, port_, addr, bytes, at);
}

void UnitMemory::fill(uint64_t addr, uint32_t bytes, Cycle at) {
  shared_->fill_request(instance_, port_, addr, bytes, at);
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
