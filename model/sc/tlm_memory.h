// TLM-2.0 modules of the memory hierarchy's ends: an RT unit's L1 (the initiator of the
// approximately-timed requests to the shared L2, model/sc/shared_cache_module.h) and the DRAM
// (a loosely-timed target, which the L2 calls in simulated-time order; another loosely-timed
// TLM memory model can be bound in its place).
// Only addresses and lengths matter: the functional model reads BVH data itself, so targets do
// not fill data buffers. No module has a thread: a transaction is a function call chain.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>

#include "model/mem/cache.h"
#include "model/mem/dram.h"
#include "model/sc/clock.h"

namespace rtsim {

// Carried by the L1's read transactions: what the read cost below the L1, filled in by a
// target that knows (the shared L2); a foreign target may ignore it.
struct ReadChargeExtension : tlm::tlm_extension<ReadChargeExtension> {
  ReadCharge charge;
  tlm::tlm_extension_base* clone() const override { return new ReadChargeExtension(*this); }
  void copy_from(const tlm::tlm_extension_base& other) override {
    charge = static_cast<const ReadChargeExtension&>(other).charge;
  }
};

// An RT unit's L1. The unit reads it by a direct call (it is the unit's own); its misses leave
// through `out` as AT transactions (BEGIN_REQ dated by the TLM delay; the data's cycle comes
// back as BEGIN_RESP, possibly well before that cycle, its delay saying when), and so do its
// posted writes. on_response runs after each response, so the owner can wake up.
class L1Module : public sc_core::sc_module, private MemoryTarget {
 public:
  tlm_utils::simple_initiator_socket<L1Module> out;

  L1Module(sc_core::sc_module_name name, const CacheConfig& config, const Clock& clock,
           std::function<void()> on_response = {});
  Cache& cache() { return cache_; }
  const Cache& cache() const { return cache_; }

 private:
  struct Transaction : tlm::tlm_generic_payload {
    ReadClient* client = nullptr;  // null: a posted write
    uint64_t token = 0;
    ReadChargeExtension* charge = nullptr;
  };
  Cycle read(uint64_t addr, uint32_t bytes, Cycle at, ReadClient* client, uint64_t token,
             ReadCharge& charge) override;
  void write(uint64_t addr, uint32_t bytes, Cycle at) override;
  // Sends a transaction; true if the target completed it at once (delay then says when).
  bool send(Transaction& t, tlm::tlm_command command, uint64_t addr, uint32_t bytes, Cycle at,
            sc_core::sc_time& delay);
  tlm::tlm_sync_enum nb_transport_bw(tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase,
                                     sc_core::sc_time& delay);
  Transaction& take();
  void give_back(Transaction& t) { free_.push_back(&t); }

  Clock clock_;
  std::function<void()> on_response_;
  std::vector<std::unique_ptr<Transaction>> pool_;
  std::vector<Transaction*> free_;
  std::vector<unsigned char> scratch_;
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
