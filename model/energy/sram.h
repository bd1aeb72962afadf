// Dynamic energy and area of an SRAM array (a cache's data array or a slice of one, a buffer)
// from its size, banks and access width, at a process node (issue 20).
// Energy: a power law in the size of the bank an access reaches, fitted in log-log by least
// squares to Horowitz's 45 nm table (ISSCC 2014, Fig. 1.1.9: a 64-bit read of an 8 KB, 32 KB
// and 1 MB SRAM costs 10, 20 and 100 pJ), proportional to the bits moved, and scaled to the node
// by sram_energy_scale. Area: the bitcells over an array efficiency (an assumption). Sources and
// what the model leaves out are in model/energy/SOURCES.md and README.md.
#pragma once

#include <cstdint>
#include <vector>

#include "model/energy/process_node.h"

namespace rtsim {

struct SramEnergyRow {
  uint64_t bytes;  // array size
  double read_pj;  // pJ: one 64-bit read
};

// E(bytes) = at_8kb_pj * (bytes / 8 KB)^exponent for a 64-bit read at 45 nm.
struct SramEnergyFit {
  double at_8kb_pj = 0;
  double exponent = 0;
  double max_error = 0;  // the largest relative error over the rows fitted
  double read_pj(uint64_t bytes) const;
};

const std::vector<SramEnergyRow>& horowitz_45nm_sram_rows();
SramEnergyFit fit_sram_energy(const std::vector<SramEnergyRow>& rows);  // at least two rows

struct SramArray {
  uint64_t bytes = 0;         // capacity
  uint32_t access_bits = 64;  // bits one access reads or writes (a line, a node)
  uint32_t banks = 1;         // an access reaches one bank of bytes / banks
  uint32_t ports = 1;         // accesses a bank starts per cycle
};

// pJ of one read of the array at the node. Each port beyond the first adds a word line and a bit
// line pair to every cell: half a port's energy more (Rixner et al., HPCA 2000: energy grows
// about as the ports, area as their square; the 0.5 is an assumption, SOURCES.md A.7).
double sram_read_pj(const SramArray& array, const ProcessNode& node);

constexpr double kSramArrayEfficiency = 0.6;  // bitcells over macro area (assumption)
// mm² of the array's bitcells and periphery at the node, times the square of its ports.
double sram_area_mm2(const SramArray& array, const ProcessNode& node);

}  // namespace rtsim
