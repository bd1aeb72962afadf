// The DRAM roofline: independent line reads at consecutive addresses, all waiting at once,
// must keep the data buses at 90% of their peak or more (refresh as configured).
#include <stdexcept>

#include <fmt/core.h>

#include "model/mem/dram_controller.h"
#include "reports/validate/checks.h"

namespace rtsim::validation {

void drain(DramController& controller, size_t reads, Cycle from, std::vector<DramReadDone>& done) {
  for (Cycle until = from; done.size() < reads; until += 4096) {
    if (until > from + 100000000)
      throw std::runtime_error("rtsim validate: the DRAM controller stopped answering reads");
    controller.advance(until, done);
  }
}

std::vector<Check> dram_roofline(const Target& target) {
  const HwConfig& preset = target.config;
  Check c{"roofline.dram", "closed_form", "independent misses saturate the DRAM's data buses"};
  c.unit = "bytes per cycle";
  if (preset.dram_model != DramModel::Banked) {
    c.skipped = "dram.model is simple: its bus is one cursor, checked by its unit tests";
    return {c};
  }
  const BankedDramConfig& dram = preset.banked_dram;
  uint32_t line = block_bytes(last_level(preset).cache);
  const uint64_t reads = 65536;
  HwConfig run = target.as_run(preset);
  DramController controller(run.banked_dram, run.clock_ghz);
  for (uint64_t i = 0; i < reads; ++i) controller.enqueue(i, i * line, line, false, 0);
  std::vector<DramReadDone> done;
  drain(controller, reads, 0, done);
  Cycle last = 0;
  for (const DramReadDone& d : done) last = std::max(last, d.ready);
  double peak = dram.peak_gb_per_s() / preset.clock_ghz;
  c.expected = peak;
  c.lo = 0.9 * peak;
  c.hi = peak;
  c.measured = double(reads * line) / double(last);
  c.source = fmt::format(
      "formula: peak = channels {} x bus_bits {} / 8 x beats_per_clock {} x clock {} MHz = "
      "{:.1f} GB/s, over the {} GHz core clock; pass from 90% of it",
      dram.channels, dram.bus_bits, dram.beats_per_clock, dram.clock_mhz, dram.peak_gb_per_s(),
      preset.clock_ghz);
  c.detail = fmt::format(
      "DramController alone: {} reads of {} bytes at consecutive addresses, "
      "all arrived at cycle 0; bytes over the cycle the last one is ready",
      reads, line);
  c.look_at = "DramController (scheduling, refresh) and dram.mapping";
  return {c};
}

}  // namespace rtsim::validation
