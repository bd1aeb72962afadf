// Test-unit energies (model/energy/test_units.h) and the node scaling of logic.
#include <gtest/gtest.h>

#include "model/energy/test_units.h"

namespace rtsim {
namespace {

TEST(TestUnitEnergy, AQB8sCountsAtHorowitzsEnergies) {
  EXPECT_NEAR(arithmetic_pj(fp32_box_test(), process_node("45nm")), 6 * 3.7 + 6 * 0.9 + 7 * 0.1,
              1e-9);
  EXPECT_NEAR(arithmetic_pj(quantized_box_test(), process_node("45nm")), 6 * 0.2 + 13 * 0.1, 1e-9);
  EXPECT_NEAR(arithmetic_pj(triangle_test(), process_node("45nm")), 29 * 3.7 + 18 * 0.9 + 3 * 0.1,
              1e-9);
  EXPECT_GT(arithmetic_pj(fp32_box_test(), process_node("7nm")) /
                arithmetic_pj(quantized_box_test(), process_node("7nm")),
            10)
      << "an 8-bit box test costs a fraction of an fp32 one";
}

TEST(TestUnitEnergy, LogicScalesByStillmakerAndBaassFits) {
  EXPECT_EQ(logic_energy_scale(process_node("45nm")), 1.0);
  EXPECT_NEAR(logic_energy_scale(process_node("12nm")), 0.172, 0.001);
  EXPECT_NEAR(logic_energy_scale(process_node("7nm")), 0.080, 0.001);
  EXPECT_NEAR(arithmetic_pj(triangle_test(), process_node("7nm")),
              arithmetic_pj(triangle_test(), process_node("45nm")) *
                  logic_energy_scale(process_node("7nm")),
              1e-9);
}

}  // namespace
}  // namespace rtsim
