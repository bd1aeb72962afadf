// Stall detection: with a memory that never answers (a foreign TLM target bound where the
// DRAM is), the run stops after stall_cycles without progress with an error that dumps every
// unit's state, instead of hanging.
#include <gtest/gtest.h>

#include <tlm_utils/simple_target_socket.h>

#include "tests/sc/sim_test_util.h"

namespace rtsim {
namespace {

// Answers every read a second after it was asked: forever, at these clock rates.
struct BlackHoleMemory : sc_core::sc_module {
  tlm_utils::simple_target_socket<BlackHoleMemory> in{"in"};
  explicit BlackHoleMemory(sc_core::sc_module_name name) : sc_module(name) {
    in.register_b_transport(this, &BlackHoleMemory::b_transport);
  }
  void b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) {
    delay += sc_core::sc_time(1, sc_core::SC_SEC);
    trans.set_response_status(tlm::TLM_OK_RESPONSE);
  }
};

TEST(SimStall, NoProgressStopsWithAStateDump) {
  test::SimScene s;
  std::vector<Ray> rays = test::mixed_rays(s.scene, 200, 1);
  std::string message = run_in_child([&] {
    HwConfig config = test::small_machine();
    config.sim.stall_cycles = 5000;
    BvhImage image = build_bvh_image(s.scene.mesh, config.bvh);
    VectorRaySource source(rays);
    BlackHoleMemory hole("hole");
    RtSimulator sim(config, image, source, 0, 0, nullptr,
                    [&](auto& socket) { socket.bind(hole.in); });
    try {
      sim.run();
    } catch (const SimStallError& e) {
      return std::string(e.what());
    }
    return std::string("no stall reported");
  });
  EXPECT_NE(message.find("no progress for 5000 cycles"), std::string::npos) << message;
  EXPECT_NE(message.find("rt0: 16 of 16 ray slots busy"), std::string::npos) << message;
  EXPECT_NE(message.find("rt1:"), std::string::npos) << message;
  EXPECT_NE(message.find("dispatch:"), std::string::npos) << message;
  EXPECT_NE(message.find("ready at cycle"), std::string::npos) << "per-ray state";
  EXPECT_NE(message.find("(12 more rays)"), std::string::npos) << "4 of 16 rays shown";
}

}  // namespace
}  // namespace rtsim
