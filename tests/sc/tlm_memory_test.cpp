// The memory hierarchy as SystemC modules: L1 -> shared L2 (connected by call, or a TLM-2.0
// approximately-timed initiator at its socket) -> DRAM (loosely or approximately timed TLM),
// requests served in time order, the configured latency sums, DRAM bandwidth under load, and a
// foreign loosely-timed TLM memory bound where the DRAM would be.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <memory>

#include <tlm_utils/simple_initiator_socket.h>

#include "model/sc/banked_dram_module.h"
#include "model/sc/shared_levels_module.h"
#include "model/sc/tlm_memory.h"
#include "tests/mem/mock_memory.h"
#include "tests/sc/timed_memory.h"

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

// An approximately-timed initiator: at cycle 0 it sends one read per (address, cycle) of its
// script, in script order, each dated by its TLM delay; records when each one's data is ready.
struct AtRequester : sc_core::sc_module {
  tlm_utils::simple_initiator_socket<AtRequester> out{"out"};
  std::vector<std::pair<uint64_t, Cycle>> script;  // (address, delay in cycles) of each read
  Cycle start = 0;                                 // the cycle it sends its script at
  std::vector<Cycle> ready;
  Clock clock;
  SC_HAS_PROCESS(AtRequester);
  explicit AtRequester(sc_core::sc_module_name name) : sc_module(name) {
    out.register_nb_transport_bw(this, &AtRequester::nb_transport_bw);
    SC_THREAD(run);
  }
  void run() {
    ready.assign(script.size(), kPending);
    if (start > 0) wait(clock.delay_to(start));
    for (size_t i = 0; i < script.size(); ++i) {
      trans.push_back(std::make_unique<tlm::tlm_generic_payload>());
      tlm::tlm_generic_payload& t = *trans.back();
      index[&t] = i;
      t.set_command(tlm::TLM_READ_COMMAND);
      t.set_address(script[i].first);
      t.set_data_ptr(data);
      t.set_data_length(64);
      t.set_streaming_width(64);
      tlm::tlm_phase phase = tlm::BEGIN_REQ;
      sc_core::sc_time delay = clock.time(script[i].second);
      out->nb_transport_fw(t, phase, delay);
    }
  }
  tlm::tlm_sync_enum nb_transport_bw(tlm::tlm_generic_payload& t, tlm::tlm_phase& phase,
                                     sc_core::sc_time& delay) {
    if (phase == tlm::BEGIN_RESP) ready[index[&t]] = clock.cycles(sc_core::sc_time_stamp() + delay);
    return tlm::TLM_COMPLETED;
  }
  std::vector<std::unique_ptr<tlm::tlm_generic_payload>> trans;
  std::map<tlm::tlm_generic_payload*, size_t> index;
  unsigned char data[64] = {};
};

CacheConfig l2_config(uint32_t hit_latency, uint32_t mshrs) {
  CacheConfig c;
  c.size_bytes = 1 << 20;
  c.line_bytes = 64;
  c.ways = 8;
  c.hit_latency = hit_latency;
  c.mshrs = mshrs;
  return c;
}

// An approximately-timed requester straight at an L2 (10-cycle tag check) in front of a DRAM.
struct L2Bench {
  L2Bench(uint32_t mshrs, const DramConfig& dram_config, const SliceLayout& layout = {})
      : l2("l2", l2_config(10, mshrs), clock, layout), dram("dram", dram_config, clock) {
    cpu.out.bind(l2.in);
    l2.out.bind(dram.in);
  }
  Clock clock;
  AtRequester cpu{"cpu"};
  SharedLevelsModule l2;
  DramModule dram;
};

TEST(TlmMemory, AnEarlierDatedRequestIsNotDelayedByALaterDatedOneSentBefore) {
  L2Bench bench(8, DramConfig{64.0, 300, 64});
  AtRequester& cpu = bench.cpu;
  cpu.script = {{0x10000, 1000}, {0x0, 10}, {0x40, 11}, {0x80, 12}};
  sc_core::sc_start();
  // Each miss reaches the DRAM after the L2's 10-cycle tag check and takes its bus for a cycle.
  EXPECT_EQ(cpu.ready[1], 10u + 10 + 1 + 300) << "served at its own cycle, before cycle 1000's";
  EXPECT_EQ(cpu.ready[2], 11u + 10 + 1 + 300);
  EXPECT_EQ(cpu.ready[3], 12u + 10 + 1 + 300);
  EXPECT_EQ(cpu.ready[0], 1000u + 10 + 1 + 300);
  EXPECT_EQ(bench.dram.dram().stats().total_latency_cycles, 4u * 301) << "no request queued";
}

TEST(TlmMemory, AThirdPartyTimedTargetAnswersBelowTheL2AtItsOwnCycles) {
  Clock clock;
  AtRequester cpu("cpu");
  SharedLevelsModule l2("l2", l2_config(10, 8), clock, {}, 20);
  test::TimedMemory memory("memory", sc_core::sc_time(100, sc_core::SC_NS));
  cpu.out.bind(l2.in);
  l2.out.bind(memory.in);
  l2.use_timed_memory(0);  // BEGIN_RESP comes at the data's own cycle
  cpu.script = {{0x10000, 1000}, {0x0, 10}, {0x40, 11}, {0x0, 50}, {0x40, 200}};
  sc_core::sc_start();
  EXPECT_EQ(cpu.ready[1], 10u + 10 + 100);
  EXPECT_EQ(cpu.ready[2], 11u + 10 + 100);
  EXPECT_EQ(cpu.ready[3], 10u + 10 + 100) << "merged into the miss in flight";
  EXPECT_EQ(cpu.ready[4], 200u + 10) << "a hit once the data is in";
  EXPECT_EQ(cpu.ready[0], 1000u + 10 + 100);
  EXPECT_EQ(memory.reads, 3);
}

// The banked DRAM below the L2: one channel, DRAM clock = core clock (1 GHz), so a first read
// is the L2's tag check, ACT, tRCD, two RDs tCCD_L apart (a 64-byte line is two 32-byte bursts
// of one bank), tCL and the second burst, and the controller latency. The same answers through
// the approximately-timed protocol and by call (the simulator's own connection).
void expect_banked_dram_timing(bool by_call) {
  Clock clock;
  BankedDramConfig config;
  config.clock_mhz = 1000;
  config.channels = 1;
  config.refresh = DramRefresh::None;
  AtRequester cpu("cpu");
  SharedLevelsModule l2("l2", l2_config(10, 8), clock, {}, 20);
  BankedDramModule dram("dram", config, clock, 1.0);
  cpu.out.bind(l2.in);
  if (by_call) {
    l2.connect_memory(dram, dram.response_lead());
  } else {
    l2.out.bind(dram.in);
    l2.use_timed_memory(dram.response_lead());
  }
  cpu.script = {{0x0, 10}, {0x1000, 500}};  // the second: the same bank and row
  sc_core::sc_start();
  const DramTiming& t = config.timing;
  uint32_t bursts = t.tCCD_L + config.burst_clocks();
  EXPECT_EQ(cpu.ready[0], 10u + 10 + t.tRCD_RD + t.tCL + bursts + config.controller_latency);
  EXPECT_EQ(cpu.ready[1], 500u + 10 + t.tCL + bursts + config.controller_latency) << "a row hit";
  EXPECT_EQ(dram.controller().stats().row_hits, 3u) << "the second burst of each line hits too";
  EXPECT_EQ(dram.controller().stats().row_misses, 1u);
}

TEST(TlmMemory, TheBankedDramSpeaksTheTimedProtocol) {
  expect_banked_dram_timing(false);
}

TEST(TlmMemory, TheBankedDramConnectedByCallAnswersAlike) {
  expect_banked_dram_timing(true);
}

TEST(TlmMemory, ManyIndependentMissesSaturateTheDramBandwidth) {
  L2Bench bench(64, DramConfig{16.0, 100, 64});
  AtRequester& cpu = bench.cpu;
  for (uint64_t i = 0; i < 4000; ++i) cpu.script.push_back({i * 64, i / 8});  // 8 lines a cycle
  sc_core::sc_start();
  Cycle last = *std::max_element(cpu.ready.begin(), cpu.ready.end());
  // From the first miss at the DRAM (cycle 10) to the end of the last transfer.
  double span = double(last - 100 - 10);
  double achieved = double(bench.dram.dram().stats().bytes) / span;
  EXPECT_NEAR(achieved / 16.0, 1.0, 0.05) << "bytes per cycle against the configured peak";
  EXPECT_GT(bench.l2.instances()[0].stats().mshr_stall_cycles, 0u)
      << "the MSHRs held the misses back";
}

TEST(TlmMemory, TheCrossbarAddsItsLatencyBothWaysAndItsPortsBoundTheBandwidth) {
  SliceLayout layout;
  layout.slices = 4;
  layout.crossbar = {5, 16.0};  // a 64-byte line holds a link for 4 cycles
  L2Bench bench(8, DramConfig{64.0, 300, 64}, layout);
  AtRequester& cpu = bench.cpu;
  cpu.script = {{0x0, 100}};
  for (uint64_t line = 0; line < 8; ++line) cpu.script.push_back({line * 64, 2000 + line});
  for (uint64_t line = 1; line < 8; ++line) cpu.script.push_back({line * 64, 5000});
  sc_core::sc_start();
  // The request (8 bytes, one cycle on each link) crosses in 5 cycles; the L2's tag check, the
  // DRAM's cycle and latency; the line crosses back: 3 more cycles on each link and 5 between.
  EXPECT_EQ(cpu.ready[0], 100u + 5 + 10 + 1 + 300 + 3 + 5 + 3);
  // Eight misses to the four slices, one a cycle, come back through the unit's one port.
  std::vector<Cycle> back(cpu.ready.begin() + 9, cpu.ready.end());
  std::sort(back.begin(), back.end());
  EXPECT_EQ(back.front(), 5000u + 5 + 10 + 3 + 5 + 3) << "L2 hits, unloaded";
  EXPECT_EQ(back.back() - back.front(), 6u * 4) << "seven lines through one port: 4 cycles each";
  CacheStats sum;
  for (uint32_t i = 0; i < 4; ++i) sum += bench.l2.instances()[0].slices[i]->stats();
  EXPECT_EQ(sum.accesses, bench.l2.instances()[0].stats().accesses);
  uint32_t used = 0;
  for (uint32_t i = 0; i < 4; ++i) used += bench.l2.instances()[0].slices[i]->stats().accesses > 0;
  EXPECT_EQ(used, 4u) << "lines hash over all slices";
  EXPECT_EQ(bench.l2.instances()[0].crossbar.units(), 1u) << "one port, the bound TLM initiator's";
}

// Two initiators, each with its own crossbar port, in front of one slice, behind links of 4
// bytes a cycle (a request's 8 bytes hold a link for 2 cycles, a line's 64 for 16). The first
// sends a read dated cycle 110, the second a cycle later one dated 109, both L2 hits. The
// crossbar is booked in time order, when the L2's calendar reaches each request, not in the
// order they were sent: the read dated earlier crosses unloaded and is answered first. (Booked
// when sent, the first read would take the slice's link first and delay the second.)
TEST(TlmMemory, TheCrossbarIsBookedInTimeOrderNotInTheOrderRequestsAreSent) {
  SliceLayout layout;
  layout.crossbar = {5, 4.0};
  L2Bench bench(8, DramConfig{64.0, 300, 64}, layout);
  AtRequester second("second");
  second.out.bind(bench.l2.in);
  bench.cpu.script = {{0x0, 110}};
  second.script = {{0x40, 108}};  // dated by its delay: sent at cycle 1, so cycle 109
  second.start = 1;
  bench.l2.warm(0x0, 128, false);
  sc_core::sc_start();
  // A transfer of n cycles has arrived in its n-th: the request 2 cycles on the up-link, 5 in
  // the switch, 2 on the slice's link; the L2's 10-cycle hit; the line 16 cycles on the slice's
  // link, 5 in the switch, 16 on the unit's.
  EXPECT_EQ(second.ready[0], 109u + 1 + 5 + 1 + 10 + 15 + 5 + 15) << "unloaded";
  EXPECT_GT(bench.cpu.ready[0], second.ready[0]) << "the read dated later, sent first, waits";
  EXPECT_GT(bench.l2.instances()[0].crossbar.slice_in(0).stats().stall_cycles, 0u);
}

// Reads through an L1 from a thread at given cycles; records each read's ready cycle.
struct L1Requester : sc_core::sc_module {
  UnitMemory l1;
  std::vector<std::pair<uint64_t, Cycle>> script;
  std::vector<Cycle> ready;
  std::vector<ReadCharge> charge;
  test::RecordingClient client;
  SC_HAS_PROCESS(L1Requester);
  L1Requester(sc_core::sc_module_name name, const CacheConfig& config)
      : sc_module(name), l1("l1", config) {
    SC_THREAD(run);
  }
  void run() {
    Clock clock;
    for (auto [addr, at] : script) {
      if (clock.time(at) > sc_core::sc_time_stamp()) wait(clock.delay_to(at));
      ReadCharge c;
      Cycle done = l1.cache().read(addr, 32, at, &client, ready.size(), c);
      while (done == kPending) {
        wait(clock.period());
        for (const auto& d : client.done) done = d.ready, c += d.charge;
        client.done.clear();
      }
      ready.push_back(done);
      charge.push_back(c);
      if (clock.time(done) > sc_core::sc_time_stamp()) wait(clock.delay_to(done));
    }
  }
};

TEST(TlmMemory, HierarchyLatenciesAreTheConfiguredSumsAndAForeignTargetBinds) {
  Clock clock;  // 1 ns cycles
  CacheConfig l1;
  l1.size_bytes = 1024;
  l1.hit_latency = 2;
  DramConfig dram_config;
  dram_config.bytes_per_cycle = 16;
  dram_config.latency = 100;

  L1Requester cpu("cpu", l1), other("other", l1);
  SharedLevelsModule l2("l2", l2_config(10, 8), clock);
  DramModule dram("dram", dram_config, clock);
  cpu.l1.connect(l2);
  other.l1.connect(l2);
  l2.out.bind(dram.in);
  cpu.script = {{0x1000, 0}, {0x1000, 200}};
  other.script = {{0x1000, 300}};

  L1Requester foreign_cpu("foreign_cpu", l1);
  SharedLevelsModule foreign_l2("foreign_l2", l2_config(10, 8), clock);
  FixedLatencyMemory foreign("foreign");
  foreign_cpu.l1.connect(foreign_l2);
  foreign_l2.out.bind(foreign.in);
  foreign_cpu.script = {{0x40, 5}};

  sc_core::sc_start();

  ASSERT_EQ(cpu.ready.size(), 2u);
  // L1 tag 2 + L2 tag 10 + DRAM 64 B at 16 B/cycle 4 + latency 100.
  EXPECT_EQ(cpu.ready[0], 2u + 10 + 4 + 100) << "a DRAM access";
  EXPECT_EQ(cpu.charge[0].accesses[1], 1u);
  EXPECT_EQ(cpu.charge[0].dram_bytes, 64u) << "the L2's fetch, charged to the read";
  EXPECT_EQ(cpu.ready[1], 200u + 2) << "an L1 hit";
  EXPECT_EQ(cpu.charge[1].hits[0], 1u);
  ASSERT_EQ(other.ready.size(), 1u);
  EXPECT_EQ(other.ready[0], 300u + 2 + 10) << "another unit's L1 miss hits in the L2";
  EXPECT_EQ(other.charge[0].hits[1], 1u);
  EXPECT_EQ(l2.instances()[0].stats().misses, 1u);
  EXPECT_EQ(dram.dram().stats().bytes, 64u);
  EXPECT_EQ(l2.instances()[0].crossbar.units(), 2u)
      << "a port per connected L1, none for the unbound socket";

  ASSERT_EQ(foreign_cpu.ready.size(), 1u);
  EXPECT_EQ(foreign_cpu.ready[0], 5u + 2 + 10 + 50) << "the foreign memory's 50 ns, through TLM";
  EXPECT_EQ(foreign.reads, 1);
}

}  // namespace
}  // namespace rtsim
