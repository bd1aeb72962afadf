// The memory hierarchy as SystemC modules: L1 -> L2 -> DRAM through TLM-2.0 sockets, and a
// foreign loosely-timed TLM memory bound where the DRAM would be.
#include <gtest/gtest.h>

#include <tlm_utils/simple_initiator_socket.h>

#include "model/sc/tlm_memory.h"

namespace rtsim {
namespace {

// A third-party style memory: fixed 50 ns, knows nothing of rtsim.
struct FixedLatencyMemory : sc_core::sc_module {
  tlm_utils::simple_target_socket<FixedLatencyMemory> in{"in"};
  int reads = 0;
  explicit FixedLatencyMemory(sc_core::sc_module_name name) : sc_module(name) {
    in.register_b_transport(this, &FixedLatencyMemory::b_transport);
  }
  void b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) {
    ++reads;
    delay += sc_core::sc_time(50, sc_core::SC_NS);
    trans.set_response_status(tlm::TLM_OK_RESPONSE);
  }
};

// Issues reads from a thread and records when each one's data is ready, in cycles.
struct Requester : sc_core::sc_module {
  tlm_utils::simple_initiator_socket<Requester> out{"out"};
  std::vector<std::pair<uint64_t, sc_core::sc_time>> script;  // (address, issue time)
  std::vector<Cycle> ready;
  Clock clock;
  SC_HAS_PROCESS(Requester);
  explicit Requester(sc_core::sc_module_name name) : sc_module(name) { SC_THREAD(run); }
  void run() {
    TlmReadPort port([this](auto& t, auto& d) { out->b_transport(t, d); }, clock);
    for (auto [addr, at] : script) {
      if (at > sc_core::sc_time_stamp()) wait(at - sc_core::sc_time_stamp());
      Cycle done = port.read(addr, 32, clock.cycles(sc_core::sc_time_stamp()));
      ready.push_back(done);
      wait(clock.time(done) - sc_core::sc_time_stamp());  // sleep until the data arrives
    }
  }
};

TEST(TlmMemory, HierarchyLatenciesAndForeignTarget) {
  Clock clock;  // 1 ns cycles
  CacheConfig l1;
  l1.size_bytes = 1024;
  l1.hit_latency = 2;
  CacheConfig l2;
  l2.size_bytes = 8192;
  l2.hit_latency = 10;
  DramConfig dram;
  dram.bytes_per_cycle = 16;
  dram.latency = 100;

  Requester cpu("cpu");
  CacheModule l1_cache("l1", l1, clock), l2_cache("l2", l2, clock);
  DramModule memory("dram", dram, clock);
  cpu.out.bind(l1_cache.in);
  l1_cache.out.bind(l2_cache.in);
  l2_cache.out.bind(memory.in);
  auto ns = [](double n) { return sc_core::sc_time(n, sc_core::SC_NS); };
  cpu.script = {{0x1000, ns(0)}, {0x1000, ns(0)}, {0x5000, ns(0)}};

  Requester other("other");
  CacheModule other_l1("other_l1", l1, clock);
  FixedLatencyMemory foreign("foreign");
  other.out.bind(other_l1.in);
  other_l1.out.bind(foreign.in);
  other.script = {{0x40, ns(5)}, {0x40, ns(5)}};

  sc_core::sc_start();

  ASSERT_EQ(cpu.ready.size(), 3u);
  // L1 tag 2 + L2 tag 10 + DRAM 64 B at 16 B/cycle 4 + latency 100.
  EXPECT_EQ(cpu.ready[0], 2u + 10 + 4 + 100) << "cold miss through L1, L2 and DRAM";
  EXPECT_EQ(cpu.ready[1], cpu.ready[0] + 2) << "then an L1 hit";
  EXPECT_EQ(cpu.ready[2], cpu.ready[1] + 116) << "another cold miss";
  EXPECT_EQ(l2_cache.cache().stats().misses, 2u);
  EXPECT_EQ(memory.dram().stats().bytes, 128u);

  ASSERT_EQ(other.ready.size(), 2u);
  EXPECT_EQ(other.ready[0], 5u + 2 + 50) << "the foreign memory's 50 ns, bound through TLM";
  EXPECT_EQ(foreign.reads, 1);
}

}  // namespace
}  // namespace rtsim
