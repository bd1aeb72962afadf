#include "model/energy/dram_energy.h"

#include <stdexcept>

namespace rtsim {

DramCommandEnergy dram_command_energy(const DramCurrents& c, const DramCommandTimes& t) {
  // mW drawn on both rails at the given currents.
  auto power = [&](double idd, double ipp) { return c.vdd * idd + c.vpp * ipp; };
  DramCommandEnergy e;
  e.act_pre_pj = (power(c.idd0, c.ipp0) - power(c.idd2n, c.ipp2n)) * t.trc;
  e.read_pj = (power(c.idd4r, c.ipp4r) - power(c.idd3n, c.ipp3n)) * t.burst;
  e.write_pj = (power(c.idd4w, c.ipp4w) - power(c.idd3n, c.ipp3n)) * t.burst;
  e.refresh_pj = (power(c.idd5b, c.ipp5b) - power(c.idd3n, c.ipp3n)) * t.trfc;
  e.active_mw = power(c.idd3n, c.ipp3n);
  e.precharged_mw = power(c.idd2n, c.ipp2n);
  return e;
}

const DramDeviceData& ddr5_4800_x8() {
  static const DramDeviceData d{
      "ddr5-4800-x8",
      "Micron MT60B 16 Gb DDR5 data sheet, -48B speed grade (IDD/IPP as transcribed in SOURCES.md "
      "D.2)",
      {1.1, 1.8, 103, 92, 142, 377, 359, 277, 8, 6, 7, 9, 37, 28},
      {32 + 16.25, 16 * 0.4167 / 2, 295},
      8 * 16,
      16,
      1024};  // 32 banks of 65,536 rows
  return d;
}

const DramDeviceData& ddr5_4800_x16() {
  static const DramDeviceData d{
      "ddr5-4800-x16",
      "Micron MT60B 16 Gb DDR5 data sheet, -48B speed grade, x16 (IDD/IPP as transcribed in "
      "SOURCES.md D.2)",
      {1.1, 1.8, 122, 92, 142, 530, 479, 277, 10, 6, 7, 9, 64, 28},
      {32 + 16.25, 16 * 0.4167 / 2, 295},
      16 * 16,
      16,
      2048};  // 16 banks of 65,536 rows
  return d;
}

const DramDeviceData& hbm2_8gb_x128() {
  static const DramDeviceData d{"hbm2-8gb-x128",
                                "DRAMsim3 configs/HBM2_8Gb_x128.ini",
                                {1.2, 0, 65, 40, 55, 390, 500, 250},
                                {34 + 14, 2, 260},
                                128 * 4,
                                8,
                                2048};  // 16 banks of 32,768 rows
  return d;
}

const DramDeviceData& gddr5x_8gb_x32() {
  constexpr double tck = 0.666;
  static const DramDeviceData d{"gddr5x-8gb-x32",
                                "DRAMsim3 configs/GDDR5X_8Gb_x32.ini",
                                {1.35, 0, 75, 45, 55, 211, 198, 286},
                                {(56 + 24) * tck, 4 * tck, 74 * tck},
                                32 * 16,
                                8,
                                4096};  // 16 banks of 16,384 rows
  return d;
}

namespace {

const std::vector<const DramDeviceData*>& devices() {
  static const std::vector<const DramDeviceData*> all = {&ddr5_4800_x8(), &ddr5_4800_x16(),
                                                         &hbm2_8gb_x128(), &gddr5x_8gb_x32()};
  return all;
}

}  // namespace

std::vector<std::string> dram_energy_device_names() {
  std::vector<std::string> names;
  for (const DramDeviceData* d : devices()) names.push_back(d->name);
  return names;
}

const DramDeviceData& dram_energy_device(const std::string& name) {
  std::string known;
  for (const DramDeviceData* d : devices()) {
    if (d->name == name) return *d;
    known += (known.empty() ? "" : ", ") + d->name;
  }
  throw std::invalid_argument("DRAM energy device '" + name + "' is unknown (" + known + ")");
}

}  // namespace rtsim
