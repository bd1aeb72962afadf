// Energy of DRAM commands from a device's datasheet currents (issue 20), by the method of
// Micron's TN-41-01 as DRAMsim3 applies it: a command's energy is the current it draws above
// the background state, times the supply voltage, times how long it draws it (mA x V x ns =
// pJ), on the core (VDD) and the word-line pump (VPP) rails. One change (SOURCES.md, D.3): an
// ACT with its PRE is charged IDD0 above IDD2N (the precharged background) over tRC, not
// IDD0 tRC - IDD3N tRAS - IDD2N tRP, which goes negative for DDR5 devices whose IDD3N exceeds
// IDD0. IDD figures are measured without output drivers: I/O energy is a separate term.
#pragma once

#include <string>
#include <vector>

namespace rtsim {

// One device's currents (mA) and supplies (V); the VPP ones 0 where the sheet has none.
struct DramCurrents {
  double vdd = 0, vpp = 0;
  double idd0 = 0, idd2n = 0, idd3n = 0, idd4r = 0, idd4w = 0, idd5b = 0;
  double ipp0 = 0, ipp2n = 0, ipp3n = 0, ipp4r = 0, ipp4w = 0, ipp5b = 0;
};

// ns: the device's row cycle (tRAS + tRP), one burst's data time, and an all-bank refresh.
struct DramCommandTimes {
  double trc = 0, burst = 0, trfc = 0;
};

struct DramCommandEnergy {
  double act_pre_pj = 0;     // an ACT and its PRE
  double read_pj = 0;        // one RD burst
  double write_pj = 0;       // one WR burst
  double refresh_pj = 0;     // one all-bank REF
  double active_mw = 0;      // background with a bank open
  double precharged_mw = 0;  // background with every bank closed
};

DramCommandEnergy dram_command_energy(const DramCurrents& currents, const DramCommandTimes& times);

// Data sets from the sources in SOURCES.md (D.2), with the times of their speed grades.
struct DramDeviceData {
  std::string name, source;
  DramCurrents currents;
  DramCommandTimes times;
  double burst_bits;  // one burst's data: device width x burst length
  double gbit;        // capacity (an HBM2 set: one channel's)
  double page_bytes;  // a row: capacity / (banks x rows)
};
const DramDeviceData& ddr5_4800_x8();    // Micron MT60B 16 Gb x8 data sheet
const DramDeviceData& ddr5_4800_x16();   // the same data sheet's x16 device
const DramDeviceData& hbm2_8gb_x128();   // DRAMsim3 configs/HBM2_8Gb_x128.ini
const DramDeviceData& gddr5x_8gb_x32();  // DRAMsim3 configs/GDDR5X_8Gb_x32.ini

std::vector<std::string> dram_energy_device_names();
// The data set of that name; std::invalid_argument naming the known ones if there is none.
const DramDeviceData& dram_energy_device(const std::string& name);

}  // namespace rtsim
