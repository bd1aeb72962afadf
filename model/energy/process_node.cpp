#include "model/energy/process_node.h"

#include <cmath>
#include <stdexcept>

namespace rtsim {

const std::vector<ProcessNode>& process_nodes() {
  static const std::vector<ProcessNode> nodes = {
      // Horowitz ISSCC 2014's node and voltage; Intel 45 nm bitcell; HP45 energy fit
      {"45nm", 0.90, 0.346, 1.018, -0.3107, 0.1539, 1.0},
      // no published 12 nm bitcell or energy fit: TSMC 16FF's bitcell, the HP16 fit, 16 nm area
      {"12nm", 0.80, 0.070, 0.2958, -0.1241, 0.03024, 0.19},
      // TSMC N7 (IEDM 2016); HP7 energy fit
      {"7nm", 0.75, 0.027, 0.1776, -0.09097, 0.02447, 0.059},
  };
  return nodes;
}

const ProcessNode& process_node(const std::string& name) {
  std::string known;
  for (const ProcessNode& node : process_nodes()) {
    if (node.name == name) return node;
    known += (known.empty() ? "" : ", ") + node.name;
  }
  throw std::invalid_argument("process node '" + name + "' is unknown (" + known + ")");
}

double sram_energy_scale(const ProcessNode& node) {
  const ProcessNode& reference = process_nodes().front();
  double volts = node.volts / reference.volts;
  return std::sqrt(node.bitcell_um2 / reference.bitcell_um2) * volts * volts;
}

double logic_energy_scale(const ProcessNode& node) {
  auto energy = [](const ProcessNode& n) {
    return n.energy_a * n.volts * n.volts + n.energy_b * n.volts + n.energy_c;
  };
  return energy(node) / energy(process_nodes().front());
}

double wire_pj_per_bit_mm(const ProcessNode& node) {
  const ProcessNode& reference = process_nodes().front();
  double volts = node.volts / reference.volts;
  return 0.121 * volts * volts;
}

double flipflop_pj_per_bit(const ProcessNode& node) {
  return 0.009 * logic_energy_scale(node);
}

double flipflop_um2_per_bit(const ProcessNode& node) {
  return 5.98 * node.area_scale;
}

}  // namespace rtsim
