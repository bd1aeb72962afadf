// Where a byte address lives in the banked DRAM: channel, rank, bank group, bank, row and
// column (in bursts). The address's burst number is split into the fields as mixed-radix
// digits, least significant field first, so counts need not be powers of two (11 channels).
// Mappings (dram.mapping), most significant field first:
//   row_bank_column_channel  row:rank:bankgroup:bank:column:channel (bursts alternate channels)
//   interleave               row:column_high:rank:bank:bankgroup:channel:column_low, with
//                            column_low the interleave_bytes a channel takes in a row
//   xor                      interleave, with the bank and bank group XORed with the row's low
//                            bits and the channel rotated by the row (Zhang et al., MICRO 2000:
//                            rows that conflict in one bank spread over the banks)
//   a custom order           the six fields joined by ':' (row:rank:bank:bankgroup:column:channel)
// The most significant field wraps: addresses beyond the capacity alias.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/mem/dram_config.h"

namespace rtsim {

struct DramAddress {
  uint32_t channel = 0, rank = 0, group = 0, bank = 0, row = 0, column = 0;
};

// Why config.mapping is impossible (empty if fine).
std::string dram_mapping_problem(const BankedDramConfig& config);

class DramAddressMap {
 public:
  explicit DramAddressMap(const BankedDramConfig& config);  // config.mapping must be valid
  DramAddress decode(uint64_t addr) const { return decode_burst(addr >> burst_shift_); }
  DramAddress decode_burst(uint64_t burst) const;  // of the burst numbered `burst` (addr / size)
  uint32_t burst_shift() const { return burst_shift_; }  // log2 of the burst's bytes

 private:
  enum class Field : uint8_t { Row, Rank, Group, Bank, Column, ColumnHigh, Channel };
  struct Digit {
    uint32_t DramAddress::*field;  // the field it adds to
    uint32_t size;
    uint32_t scale;  // of its value in the field (column_high: column_low_ columns)
    uint32_t shift;  // log2(size) if a power of two, else kNoShift
  };
  static constexpr uint32_t kNoShift = ~0u;
  std::vector<Digit> digits_;  // least significant first
  uint32_t burst_shift_;
  uint32_t column_low_ = 1;  // interleave: bursts of a row in one channel before the next
  bool hashed_ = false;      // xor
  uint32_t banks_, groups_, channels_;
};

}  // namespace rtsim
