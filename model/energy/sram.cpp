#include "model/energy/sram.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rtsim {
namespace {

constexpr double kReferenceBytes = 8 * 1024;
constexpr double kReferenceBits = 64;

}  // namespace

double SramEnergyFit::read_pj(uint64_t bytes) const {
  return at_8kb_pj * std::pow(double(bytes) / kReferenceBytes, exponent);
}

const std::vector<SramEnergyRow>& horowitz_45nm_sram_rows() {
  static const std::vector<SramEnergyRow> rows = {
      {8 * 1024, 10.0}, {32 * 1024, 20.0}, {1024 * 1024, 100.0}};
  return rows;
}

SramEnergyFit fit_sram_energy(const std::vector<SramEnergyRow>& rows) {
  if (rows.size() < 2) throw std::invalid_argument("fit_sram_energy: needs two rows at least");
  double n = double(rows.size()), sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const SramEnergyRow& row : rows) {
    double x = std::log(double(row.bytes) / kReferenceBytes), y = std::log(row.read_pj);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  SramEnergyFit fit;
  fit.exponent = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  fit.at_8kb_pj = std::exp((sy - fit.exponent * sx) / n);
  for (const SramEnergyRow& row : rows)
    fit.max_error = std::max(fit.max_error, std::abs(fit.read_pj(row.bytes) / row.read_pj - 1));
  return fit;
}

double sram_read_pj(const SramArray& array, const ProcessNode& node) {
  static const SramEnergyFit fit = fit_sram_energy(horowitz_45nm_sram_rows());
  uint64_t bank_bytes = array.bytes / std::max<uint32_t>(array.banks, 1);
  double ports = 1 + 0.5 * (std::max<uint32_t>(array.ports, 1) - 1);
  return fit.read_pj(bank_bytes) * (array.access_bits / kReferenceBits) * sram_energy_scale(node) *
         ports;
}

double sram_area_mm2(const SramArray& array, const ProcessNode& node) {
  double bits = double(array.bytes) * 8, ports = std::max<uint32_t>(array.ports, 1);
  return bits * node.bitcell_um2 / kSramArrayEfficiency * ports * ports * 1e-6;
}

}  // namespace rtsim
