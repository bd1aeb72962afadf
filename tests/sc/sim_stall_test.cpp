// Stall detection. A slow memory (a foreign TLM target bound where the DRAM is, answering a
// second after each read) is not a stall: the run waits for the data it was promised. A run with
// no progress and nothing scheduled stops after stall_cycles with an error instead of hanging
// (the watchdog on its own, as no working model gets there), and the state dump such an error
// carries names every module and ray.
#include <regex>

#include <gtest/gtest.h>

#include <tlm_utils/simple_target_socket.h>

#include "model/sc/stall_watchdog.h"
#include "tests/sc/sim_test_util.h"

namespace rtsim {
namespace {

// Answers every read a second after it was asked (1.5e9 cycles at these clock rates).
struct SlowMemory : sc_core::sc_module {
  tlm_utils::simple_target_socket<SlowMemory> in{"in"};
  explicit SlowMemory(sc_core::sc_module_name name) : sc_module(name) {
    in.register_b_transport(this, &SlowMemory::b_transport);
  }
  void b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) {
    delay += sc_core::sc_time(1, sc_core::SC_SEC);
    trans.set_response_status(tlm::TLM_OK_RESPONSE);
  }
};

TEST(SimStall, ASlowMemoryIsNotAStall) {
  test::SimScene s;
  std::vector<Ray> rays = test::mixed_rays(s.scene, 20, 1);  // camera rays and their children
  std::string result = run_in_child([&] {
    HwConfig config = test::small_machine();
    config.sim.stall_cycles = 5000;
    BvhImage image = build_bvh_image(s.scene.mesh, config.bvh);
    VectorRaySource source(rays);
    SlowMemory memory("slow");
    RtSimulator sim(config, image, source, 0, 0, nullptr,
                    [&](SharedLevelsModule& l2) { l2.out.bind(memory.in); });
    try {
      sim.run();
    } catch (const SimStallError& e) {
      return std::string(e.what());
    }
    return std::to_string(sim.rays()) + " rays, " + std::to_string(sim.cycles() > 1000000000);
  });
  EXPECT_EQ(result, std::to_string(rays.size()) + " rays, 1");
}

// Runs a watchdog alone: one unit running that never progresses; next_activity as given.
std::string watchdog_alone(uint64_t stall_cycles, std::function<Cycle()> next_activity) {
  return run_in_child([&] {
    SimControl control;
    control.units_running = 1;
    Clock clock;
    StallWatchdog watchdog("watchdog", stall_cycles, clock, control, next_activity,
                           [] { return std::string("(the state)"); });
    sc_core::sc_start();
    return control.stall_report + " | stopped at cycle " +
           std::to_string(clock.cycles(sc_core::sc_time_stamp()));
  });
}

TEST(SimStall, NoProgressAndNothingScheduledStopsAtTheDeadline) {
  std::string report = watchdog_alone(5000, [] { return kPending; });
  EXPECT_EQ(report,
            "no progress for 5000 cycles and nothing scheduled to make any (last progress at "
            "cycle 0, now cycle 5000, 1 units running; sim.stall_cycles = 5000); state:\n"
            "(the state) | stopped at cycle 5000");
}

TEST(SimStall, PromisedDataDefersTheDeadlineUntilItIsOverdue) {
  // Data promised for cycle 20000 that never brings progress: stuck from 20000 + 5000 on.
  std::string report = watchdog_alone(5000, [] { return Cycle(20000); });
  EXPECT_NE(report.find("no progress for 25000 cycles"), std::string::npos) << report;
  EXPECT_NE(report.find("stopped at cycle 25000"), std::string::npos) << report;
}

// The banked DRAM takes the decisions of a cycle up to its response lead later (hundreds of
// cycles), or in a delta cycle for a request that comes late: requests it holds are work
// scheduled, so a stall_cycles below that is no stall.
TEST(SimStall, AStallCyclesBelowTheDramLatencyIsNoStall) {
  test::SimScene s;
  std::vector<Ray> rays = test::mixed_rays(s.scene, 200, 1);
  auto run = [&](uint64_t stall_cycles) {
    return run_in_child([&] {
      HwConfig config = test::small_machine();
      config.sim.stall_cycles = stall_cycles;
      config.banked_dram.controller_latency = 300;
      BvhImage image = build_bvh_image(s.scene.mesh, config.bvh);
      VectorRaySource source(rays);
      RtSimulator sim(config, image, source);
      try {
        sim.run();
      } catch (const SimStallError& e) {
        return std::string(e.what());
      }
      return std::to_string(sim.rays()) + " rays in " + std::to_string(sim.cycles()) + " cycles";
    });
  };
  for (uint64_t stall_cycles : {10, 200000}) {
    std::string result = run(stall_cycles);
    EXPECT_EQ(result.find(std::to_string(rays.size()) + " rays in "), 0u) << result;
  }
}

// An approximately-timed memory that takes every request and never answers a read.
struct SilentMemory : sc_core::sc_module {
  tlm_utils::simple_target_socket<SilentMemory> in{"in"};
  explicit SilentMemory(sc_core::sc_module_name name) : sc_module(name) {
    in.register_nb_transport_fw(this, &SilentMemory::nb_transport_fw);
  }
  tlm::tlm_sync_enum nb_transport_fw(tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase,
                                     sc_core::sc_time&) {
    trans.set_response_status(tlm::TLM_OK_RESPONSE);
    if (trans.is_write()) return tlm::TLM_COMPLETED;
    phase = tlm::END_REQ;
    return tlm::TLM_UPDATED;
  }
};

// A DRAM that never answers stalls the run; the dump names each request waiting in the shared
// levels: where it is, the unit, slot and ray it is for, what it waits for and since when
// (oldest first), and each read waiting in a unit's own level. Every ray reads the root node
// first: the two units' first rays missed its two lines in their L1s, the others merged there;
// rt1's misses merged into rt0's at the L2.
TEST(SimStall, TheStallDumpNamesEveryWaitingRequest) {
  test::SimScene s;
  std::vector<Ray> rays = test::mixed_rays(s.scene, 200, 1);
  std::string report = run_in_child([&] {
    HwConfig config = test::small_machine();
    config.sim.stall_cycles = 5000;
    BvhImage image = build_bvh_image(s.scene.mesh, config.bvh);
    VectorRaySource source(rays);
    SilentMemory memory("silent");
    SharedLevelsModule* shared = nullptr;
    RtSimulator sim(config, image, source, 0, 0, nullptr, [&](SharedLevelsModule& l2) {
      l2.out.bind(memory.in);
      l2.use_timed_memory(0);
      shared = &l2;
    });
    try {
      sim.run();
    } catch (const SimStallError& e) {
      return std::string(e.what()) + "| at most 4:\n" + shared->waiting(4);
    }
    return std::string("no stall");
  });
  const std::string l2 = "  l2 slice 0: read of 64 bytes at 0x100000", dram = "  dram below l2: ";
  const std::string lines[] = {
      l2 + "00 for rt0 slot 0 ray 0 waits for the level below since cycle 16\n",
      l2 + "40 for rt0 slot 0 ray 0 waits for the level below since cycle 16\n",
      l2 + "00 for rt1 slot 0 ray 16 waits for the level below since cycle 20\n",
      l2 + "40 for rt1 slot 0 ray 16 waits for the level below since cycle 20\n",
      dram +
          "read of 64 bytes at 0x10000000 for rt0 slot 0 ray 0 waits for the DRAM since cycle 36\n",
      dram +
          "read of 64 bytes at 0x10000040 for rt0 slot 0 ray 0 waits for the DRAM since cycle "
          "36\n"};
  std::string all, first4;
  for (int i = 0; i < 6; ++i) (i < 4 ? first4 : all) += lines[i];
  all = first4 + all;
  EXPECT_NE(report.find("next at cycle 18446744073709551615\n" + all + "|"), std::string::npos)
      << report;
  EXPECT_NE(report.find("| at most 4:\n" + first4 + "  (2 more requests)\n"), std::string::npos)
      << report;
  // In rt0's L1, all 16 rays wait for the two lines' misses: ray 0's, which the others joined.
  const std::string l1 = "  rt0.l1: read of 0x10000000 for rt0 slot ";
  EXPECT_NE(report.find(l1 + "0 ray 0 waits for the level below since cycle 16\n" + l1 +
                        "1 ray 1 waits for the level below since cycle 16\n"),
            std::string::npos)
      << report;
  EXPECT_NE(report.find("  rt0.l1: read of 0x10000000 for rt0 slot 15 ray 15 waits for the level "
                        "below since cycle 16\n  rt0.l1: read of 0x10000040 for rt0 slot 0 ray 0 "
                        "waits for the level below since cycle 16\n"),
            std::string::npos)
      << report;
  EXPECT_NE(report.find("  (12 more reads)\nrt1: "), std::string::npos) << "20 of 32 shown";
}

// Takes the simulator's state dump when the first ray retires (rt0's), with the machine full.
struct DumpAtFirstRetire : RayRetireListener {
  const RtSimulator* sim = nullptr;
  std::string dump;
  void retired(const RayContext&, Cycle) override {
    if (dump.empty()) dump = sim->dump();
  }
};

TEST(SimStall, TheStateDumpNamesEveryModuleAndSomeRays) {
  test::SimScene s;
  std::vector<Ray> rays = test::mixed_rays(s.scene, 200, 1);
  std::string dump = run_in_child([&] {
    HwConfig config = test::small_machine();
    BvhImage image = build_bvh_image(s.scene.mesh, config.bvh);
    VectorRaySource source(rays);
    DumpAtFirstRetire listener;
    RtSimulator sim(config, image, source, 0, 0, &listener);
    listener.sim = &sim;
    sim.run();
    return listener.dump;
  });
  EXPECT_NE(dump.find("rt0: 15 of 16 ray slots busy"), std::string::npos) << dump;
  EXPECT_NE(dump.find("rt1: 16 of 16 ray slots busy"), std::string::npos) << dump;
  EXPECT_NE(dump.find("dispatch:"), std::string::npos) << dump;
  EXPECT_NE(dump.find("ready at cycle"), std::string::npos) << "per-ray state";
  EXPECT_NE(dump.find("(12 more rays)"), std::string::npos) << "4 of rt1's 16 rays shown";
}

}  // namespace
}  // namespace rtsim
