// Stall detection. A slow memory (a foreign TLM target bound where the DRAM is, answering a
// second after each read) is not a stall: the run waits for the data it was promised. A run with
// no progress and nothing scheduled stops after stall_cycles with an error instead of hanging
// (the watchdog on its own, as no working model gets there), and the state dump such an error
// carries names every module and ray.
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
