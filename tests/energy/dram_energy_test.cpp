// DRAM command energies (model/energy/dram_energy.h) from each source's currents: the derived
// values of SOURCES.md (D.4), and HBM2's energy per bit against the published figure.
#include <gtest/gtest.h>

#include "model/energy/dram_energy.h"

namespace rtsim {
namespace {

void expect_within(double value, double expected, double relative, const char* what) {
  EXPECT_NEAR(value, expected, expected * relative) << what;
}

TEST(DramEnergy, Ddr5CommandsFromMicronsCurrentsOnBothRails) {
  DramCommandEnergy e = dram_command_energy(ddr5_4800_x8().currents, ddr5_4800_x8().times);
  expect_within(e.act_pre_pj, 758, 0.002, "ACT+PRE: IDD0 and IPP0 above the precharged rails");
  expect_within(e.read_pj, 874, 0.002, "RD");
  expect_within(e.write_pj, 976, 0.002, "WR");
  expect_within(e.refresh_pj, 55.0e3, 0.002, "REF");
  expect_within(e.active_mw, 168.8, 0.002, "IDD3N and IPP3N");
  expect_within(e.precharged_mw, 112.0, 0.002, "IDD2N and IPP2N");
  EXPECT_GT(e.act_pre_pj, 0) << "IDD3N > IDD0 on this sheet: the DRAMsim3 form goes negative";
}

TEST(DramEnergy, Ddr5X16CommandsFromTheSameSheet) {
  const DramDeviceData& d = ddr5_4800_x16();
  DramCommandEnergy e = dram_command_energy(d.currents, d.times);
  expect_within(e.act_pre_pj, 1940, 0.002, "ACT+PRE (SOURCES.md D.4)");
  expect_within(e.read_pj, 1435, 0.002, "RD");
  expect_within(e.write_pj, 1578, 0.002, "WR");
  EXPECT_EQ(&dram_energy_device("ddr5-4800-x16"), &d);
  EXPECT_THROW(dram_energy_device("gddr7"), std::invalid_argument);
}

TEST(DramEnergy, Hbm2AndGddr5xCommandsFromDramsim3sCurrents) {
  DramCommandEnergy h = dram_command_energy(hbm2_8gb_x128().currents, hbm2_8gb_x128().times);
  expect_within(h.act_pre_pj, 1440, 0.002, "HBM2 ACT+PRE");
  expect_within(h.read_pj, 804, 0.002, "HBM2 RD");
  expect_within(h.write_pj, 1068, 0.002, "HBM2 WR");
  expect_within(h.refresh_pj, 60.84e3, 0.002, "HBM2 REF");
  DramCommandEnergy g = dram_command_energy(gddr5x_8gb_x32().currents, gddr5x_8gb_x32().times);
  expect_within(g.act_pre_pj, 2158, 0.002, "GDDR5X ACT+PRE");
  expect_within(g.read_pj, 561, 0.002, "GDDR5X RD");
  expect_within(g.write_pj, 514, 0.002, "GDDR5X WR");
  expect_within(g.refresh_pj, 15.4e3, 0.003, "GDDR5X REF");
}

// pJ per bit of reads in a row each (random) or all in open rows (streaming), with the active
// background over the burst and refresh's share at one REF every 3.9 µs.
double read_pj_per_bit(const DramDeviceData& d, bool random) {
  DramCommandEnergy e = dram_command_energy(d.currents, d.times);
  double per_burst = e.read_pj + (random ? e.act_pre_pj : 0) + e.active_mw * d.times.burst +
                     e.refresh_pj * d.times.burst / 3900;
  return per_burst / d.burst_bits;
}

TEST(DramEnergy, Hbm2CoreEnergyBracketsThePublishedFigure) {
  // O'Connor et al. (MICRO 2017): HBM2 takes 3.97 pJ per bit, of which 0.22 is I/O.
  double stream = read_pj_per_bit(hbm2_8gb_x128(), false);
  double random = read_pj_per_bit(hbm2_8gb_x128(), true);
  EXPECT_NEAR(stream, 1.89, 0.01);
  EXPECT_NEAR(random, 4.70, 0.01);
  EXPECT_LT(stream, 3.97 - 0.22);
  EXPECT_GT(random, 3.97 - 0.22);
}

}  // namespace
}  // namespace rtsim
