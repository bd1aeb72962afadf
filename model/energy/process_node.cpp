#include "model/energy/process_node.h"

#include <cmath>

namespace rtsim {

const std::vector<ProcessNode>& process_nodes() {
  static const std::vector<ProcessNode> nodes = {
      {"45nm", 0.90, 0.346},  // Horowitz ISSCC 2014's node and voltage; Intel 45 nm bitcell
      {"12nm", 0.80, 0.070},  // no published 12 nm bitcell: TSMC 16FF's
      {"7nm", 0.75, 0.027},   // TSMC N7 (IEDM 2016)
  };
  return nodes;
}

const ProcessNode* find_process_node(const std::string& name) {
  for (const ProcessNode& node : process_nodes())
    if (node.name == name) return &node;
  return nullptr;
}

double sram_energy_scale(const ProcessNode& node) {
  const ProcessNode& reference = process_nodes().front();
  double volts = node.volts / reference.volts;
  return std::sqrt(node.bitcell_um2 / reference.bitcell_um2) * volts * volts;
}

}  // namespace rtsim
