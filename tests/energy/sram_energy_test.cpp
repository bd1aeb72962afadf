// The SRAM energy and area model (model/energy/sram.h) against the tables it comes from.
#include <gtest/gtest.h>

#include <cmath>

#include "model/energy/sram.h"

namespace rtsim {
namespace {

TEST(SramEnergy, TheFitReproducesHorowitzsRowsWithinItsStatedError) {
  SramEnergyFit fit = fit_sram_energy(horowitz_45nm_sram_rows());
  EXPECT_LT(fit.max_error, 0.025);
  EXPECT_NEAR(fit.exponent, 0.4726, 0.0005);
  EXPECT_NEAR(fit.at_8kb_pj, 10.16, 0.01);
  for (const SramEnergyRow& row : horowitz_45nm_sram_rows()) {
    double modelled = sram_read_pj({row.bytes, 64, 1}, process_node("45nm"));
    EXPECT_NEAR(modelled, row.read_pj, row.read_pj * fit.max_error + 1e-9) << row.bytes << " bytes";
  }
}

TEST(SramEnergy, AFitOfTwoRowsPassesThroughBoth) {
  SramEnergyFit fit = fit_sram_energy({{8192, 10.0}, {32768, 20.0}});
  EXPECT_NEAR(fit.exponent, 0.5, 1e-12);
  EXPECT_NEAR(fit.read_pj(131072), 40.0, 1e-9);
  EXPECT_LT(fit.max_error, 1e-12);
  EXPECT_THROW(fit_sram_energy({{8192, 10.0}}), std::invalid_argument);
}

TEST(SramEnergy, ScaledTo12nmAn8KBReadAgreesWithDallysFormula) {
  // Dally, Turakhia and Han (CACM 2020), 14 nm: 50 + 0.022 sqrt(bits) fJ per bit read.
  double dally_fj_per_bit = 50 + 0.022 * std::sqrt(8192.0 * 8);
  double modelled_fj_per_bit = sram_read_pj({8192, 64, 1}, process_node("12nm")) / 64 * 1000;
  EXPECT_NEAR(modelled_fj_per_bit, dally_fj_per_bit, 0.15 * dally_fj_per_bit);
  EXPECT_NEAR(sram_energy_scale(process_node("12nm")), 0.355, 0.001);
  EXPECT_NEAR(sram_energy_scale(process_node("7nm")), 0.194, 0.001);
  EXPECT_EQ(sram_energy_scale(process_node("45nm")), 1.0);
  EXPECT_THROW(process_node("3nm"), std::invalid_argument);
}

TEST(SramEnergy, BanksAndWidthSetWhatAnAccessCosts) {
  const ProcessNode& n7 = process_node("7nm");
  double line = sram_read_pj({1 << 20, 512, 1}, n7);
  EXPECT_NEAR(line, 8 * sram_read_pj({1 << 20, 64, 1}, n7), 1e-9) << "energy follows the bits";
  double banked = sram_read_pj({1 << 20, 512, 16}, n7);
  EXPECT_NEAR(banked, sram_read_pj({1 << 16, 512, 1}, n7), 1e-9) << "an access reaches one bank";
  EXPECT_LT(banked, line / 3) << "a 16th of the array costs about a quarter (square-root law)";
}

TEST(SramEnergy, AreaIsTheBitcellsOverTheArrayEfficiency) {
  EXPECT_NEAR(sram_area_mm2({1 << 20, 64, 1}, process_node("7nm")), 8388608 * 0.027 / 0.6 * 1e-6,
              1e-9);
  EXPECT_NEAR(sram_area_mm2({1 << 20, 64, 1}, process_node("7nm")), 0.3775, 0.0001);
  EXPECT_NEAR(sram_area_mm2({1 << 20, 64, 1}, process_node("45nm")), 4.84, 0.01);
}

TEST(SramEnergy, EachPortAddsHalfAReadAndTheAreaGrowsAsTheirSquare) {
  const ProcessNode& n7 = process_node("7nm");
  SramArray one{65536, 512, 4, 1}, two{65536, 512, 4, 2};
  EXPECT_NEAR(sram_read_pj(two, n7) / sram_read_pj(one, n7), 1.5, 1e-12);
  EXPECT_NEAR(sram_area_mm2(two, n7) / sram_area_mm2(one, n7), 4, 1e-12);
  EXPECT_EQ(sram_read_pj({65536, 512, 4, 0}, n7), sram_read_pj(one, n7)) << "0 ports: one";
}

}  // namespace
}  // namespace rtsim
