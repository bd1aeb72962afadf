// The banked DRAM's configuration: organisation, address mapping, timing (in DRAM command
// clocks, tCK) and controller policy. Presets with their sources are in configs/dram/; the keys
// are read in model/config/hw_config.cpp (`[dram]`, `[dram.timing]`).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rtsim {

// Constraints between commands, in DRAM clocks (tCK), named as in the JEDEC standards.
struct DramTiming {
  uint32_t tCL = 28;      // RD to its first data
  uint32_t tCWL = 7;      // WR to its first data
  uint32_t tRCD_RD = 30;  // ACT to RD of the same bank
  uint32_t tRCD_WR = 19;  // ACT to WR of the same bank
  uint32_t tRP = 30;      // PRE to ACT of the same bank
  uint32_t tRAS = 61;     // ACT to PRE of the same bank
  uint32_t tRC = 91;      // ACT to ACT of the same bank
  uint32_t tCCD_S = 2;    // column command to column command, other bank group
  uint32_t tCCD_L = 6;    // column command to column command, same bank group
  uint32_t tRRD_S = 8;    // ACT to ACT, other bank group
  uint32_t tRRD_L = 8;    // ACT to ACT, same bank group
  uint32_t tFAW = 32;     // window in which a rank takes at most four ACTs
  uint32_t tWTR_S = 11;   // end of write data to RD, other bank group
  uint32_t tWTR_L = 13;   // end of write data to RD, same bank group
  uint32_t tWR = 30;      // end of write data to PRE of the same bank (write recovery)
  uint32_t tRTP = 5;      // RD to PRE of the same bank
  uint32_t tRTW = 25;     // RD to WR of the same rank (read-to-write turnaround)
  uint32_t tRTRS = 2;     // gap on the data bus when it passes to another rank
  uint32_t tREFI = 3800;  // all-bank refresh interval (0: no refresh)
  uint32_t tRFC = 360;    // all-bank refresh: the rank is blocked this long
  uint32_t tREFIpb = 0;   // per-bank refresh interval (one bank after the other); 0: none
  uint32_t tRFCpb = 120;  // per-bank refresh: the bank is blocked this long
};

enum class DramPagePolicy : uint8_t { Open, Closed };
enum class DramRefresh : uint8_t { AllBank, PerBank, None };

struct BankedDramConfig {
  std::string preset;                  // the configs/dram preset it was built from ("" none)
  double clock_mhz = 2000;             // MHz: command clock CK (tCK = 1 / clock)
  uint32_t channels = 8;               // independent channels, each with its controller queue
  uint32_t ranks = 1;                  // ranks per channel (share the channel's buses)
  uint32_t bank_groups = 4;            // bank groups per rank
  uint32_t banks_per_group = 4;        // banks per bank group
  uint32_t rows = 16384;               // rows per bank
  uint32_t row_bytes = 2048;           // bytes: a row (page) of one channel
  uint32_t bus_bits = 16;              // bits: data bus width of a channel
  uint32_t burst_length = 16;          // beats: transfers of one RD or WR
  uint32_t beats_per_clock = 8;        // transfers per CK (data rate / CK)
  std::string mapping = "interleave";  // address mapping (dram_mapping_names, or a field order)
  uint32_t interleave_bytes = 256;     // bytes: consecutive bytes per channel (interleave, xor)
  DramPagePolicy page_policy = DramPagePolicy::Open;
  DramRefresh refresh = DramRefresh::AllBank;
  uint32_t read_queue = 32;          // entries per channel: a request's bursts in one row
  uint32_t write_queue = 32;         // entries per channel
  uint32_t write_high = 24;          // writes queued that start a drain
  uint32_t write_low = 8;            // a drain stops at this many
  uint32_t starvation_cap = 16;      // younger row hits served before the oldest request
  uint32_t controller_latency = 20;  // core cycles: controller and PHY, added to every read
  DramTiming timing;
  // Energy (model/energy/design_energy.h): the device whose data-sheet currents stand for this
  // one's, and the I/O energy that currents measured without output drivers leave out.
  std::string energy_device = "gddr5x-8gb-x32";
  double io_pj_per_bit = 6;

  uint32_t banks() const { return bank_groups * banks_per_group; }  // per rank
  uint32_t burst_bytes() const { return bus_bits / 8 * burst_length; }
  uint32_t burst_clocks() const { return burst_length / beats_per_clock; }  // data bus tCK
  // GB/s of all channels' data buses.
  double peak_gb_per_s() const {
    return double(channels) * bus_bits / 8 * beats_per_clock * clock_mhz / 1000;
  }
};

// Named mappings: row_bank_column_channel, interleave, xor; a custom one is a field order,
// most significant first, of row, rank, bankgroup, bank, column, channel joined by ':'.
std::vector<std::string> dram_mapping_names();
// Why the config is impossible (empty if fine), naming the key: sizes, powers of two, a
// mapping that does not name every field once, and timings that break the standards'
// relations (tRC >= tRAS + tRP, tRAS >= tRCD_RD, each _L >= its _S, tREFI > tRFC ...).
std::string banked_dram_config_problem(const BankedDramConfig& config);

}  // namespace rtsim
