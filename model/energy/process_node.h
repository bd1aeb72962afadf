// Process nodes the energy and area model is set at (issue 20): a node's supply voltage and its
// high-density 6T SRAM bitcell, and how SRAM access energy scales from the 45 nm figures the
// model is fitted to. Every figure's source is in model/energy/SOURCES.md.
#pragma once

#include <string>
#include <vector>

namespace rtsim {

struct ProcessNode {
  std::string name;    // "45nm", "12nm", "7nm"
  double volts;        // V: supply voltage assumed at the node
  double bitcell_um2;  // µm²: high-density 6T SRAM bitcell
  // Stillmaker and Baas (2017): a logic gate's energy at the node goes as a V² + b V + c.
  double energy_a, energy_b, energy_c;
  double area_scale;  // logic area at the node over 45 nm's (Stillmaker and Baas's area factor)
};

const std::vector<ProcessNode>& process_nodes();  // 45 nm first: the reference
// The node of that name; std::invalid_argument naming the known ones if there is none.
const ProcessNode& process_node(const std::string& name);

// A node's SRAM access energy over 45 nm's at the same size: an access charges word and bit
// lines whose length follows the cell pitch (the square root of the bitcell's area), at C V².
double sram_energy_scale(const ProcessNode& node);
// A node's logic (arithmetic) energy over 45 nm's, by Stillmaker and Baas's fit of each node.
double logic_energy_scale(const ProcessNode& node);

// pJ to move one bit one mm of on-chip wire: Keckler et al.'s 121 fJ at 40 nm and 0.9 V, whose
// capacitance per mm stays as nodes shrink, so it scales as V² (SOURCES.md, E).
double wire_pj_per_bit_mm(const ProcessNode& node);
// A flip-flop bit (ray state, short stacks): Aladdin's 40 nm read of 0.009 pJ and 5.98 µm²,
// taken as 45 nm's and scaled as logic (SOURCES.md, A.5).
double flipflop_pj_per_bit(const ProcessNode& node);
double flipflop_um2_per_bit(const ProcessNode& node);

}  // namespace rtsim
