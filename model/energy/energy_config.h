// The `[energy]` section of the hardware config (issue 20): the process node the energy and
// area model is set at, and the figures no source fixes (leakage, the L1-to-L2 distance), with
// their defaults' reasons in model/energy/README.md. DRAM devices are per preset ([dram.energy]).
#pragma once

#include <string>

namespace rtsim {

struct EnergyConfig {
  std::string node = "7nm";          // a process_nodes() name
  double sram_leak_mw_per_kb = 0.4;  // mW per KB of SRAM (CACTI's band: 0.4 to 2)
  double logic_leak_share = 0.1;     // test units and registers: static over peak dynamic power
  double wire_mm = 5;                // mm: how far a byte travels between an L1 and the L2
};

}  // namespace rtsim
