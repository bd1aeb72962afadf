#include "model/mem/dram_config.h"

#include <fmt/format.h>

#include "model/mem/dram_address.h"

namespace rtsim {
namespace {

bool power_of_two(uint64_t x) {
  return x && !(x & (x - 1));
}

// The first relation between timings that does not hold, as "tRC (40) must be at least ...".
std::string timing_problem(const BankedDramConfig& c) {
  const DramTiming& t = c.timing;
  struct AtLeast {
    const char* name;
    uint32_t value;
    const char* bound_name;
    uint32_t bound;
  };
  for (const AtLeast& r : {AtLeast{"tRC", t.tRC, "tRAS + tRP", t.tRAS + t.tRP},
                           {"tRAS", t.tRAS, "tRCD_RD", t.tRCD_RD},
                           {"tCCD_L", t.tCCD_L, "tCCD_S", t.tCCD_S},
                           {"tRRD_L", t.tRRD_L, "tRRD_S", t.tRRD_S},
                           {"tWTR_L", t.tWTR_L, "tWTR_S", t.tWTR_S},
                           {"tCCD_S", t.tCCD_S,
                            "the burst on the data bus (burst_length / "
                            "beats_per_clock)",
                            c.burst_clocks()},
                           {"tCL", t.tCL, "1", 1},
                           {"tRCD_RD", t.tRCD_RD, "1", 1},
                           {"tRCD_WR", t.tRCD_WR, "1", 1},
                           {"tRP", t.tRP, "1", 1},
                           {"tRRD_S", t.tRRD_S, "1", 1}})
    if (r.value < r.bound)
      return fmt::format("timing.{} ({}) must be at least {} ({})", r.name, r.value, r.bound_name,
                         r.bound);
  if (c.refresh == DramRefresh::AllBank && t.tREFI <= t.tRFC)
    return fmt::format("timing.tREFI ({}) must be above tRFC ({}) with all-bank refresh", t.tREFI,
                       t.tRFC);
  if (c.refresh == DramRefresh::PerBank && t.tREFIpb <= t.tRFCpb)
    return fmt::format("timing.tREFIpb ({}) must be above tRFCpb ({}) with per-bank refresh",
                       t.tREFIpb, t.tRFCpb);
  return {};
}

}  // namespace

std::vector<std::string> dram_mapping_names() {
  return {"row_bank_column_channel", "interleave", "xor"};
}

std::string banked_dram_config_problem(const BankedDramConfig& c) {
  if (!(c.clock_mhz > 0)) return "clock_mhz must be positive";
  if (c.bus_bits % 8 != 0) return "bus_bits must be a multiple of 8";
  if (c.burst_length % c.beats_per_clock != 0)
    return fmt::format("burst_length ({}) must be a multiple of beats_per_clock ({})",
                       c.burst_length, c.beats_per_clock);
  if (!power_of_two(c.burst_bytes()))
    return fmt::format("a burst (bus_bits / 8 * burst_length = {} bytes) must be a power of two",
                       c.burst_bytes());
  if (c.row_bytes % c.burst_bytes() != 0 || c.row_bytes < c.burst_bytes())
    return fmt::format("row_bytes ({}) must be a multiple of the burst ({} bytes)", c.row_bytes,
                       c.burst_bytes());
  if (c.interleave_bytes % c.burst_bytes() != 0 || c.interleave_bytes > c.row_bytes)
    return fmt::format(
        "interleave_bytes ({}) must be a multiple of the burst ({} bytes) and at most row_bytes",
        c.interleave_bytes, c.burst_bytes());
  std::string mapping = dram_mapping_problem(c);
  if (!mapping.empty()) return mapping;
  if (c.write_low >= c.write_high || c.write_high > c.write_queue)
    return fmt::format("write_low ({}) < write_high ({}) <= write_queue ({}) must hold",
                       c.write_low, c.write_high, c.write_queue);
  return timing_problem(c);
}

}  // namespace rtsim
