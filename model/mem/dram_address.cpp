#include "model/mem/dram_address.h"

#include <algorithm>
#include <sstream>

namespace rtsim {
namespace {

const char* const kFieldNames[] = {"row", "rank", "bankgroup", "bank", "column", "channel"};

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, ':');) parts.push_back(part);
  return parts;
}

bool is_named(const std::string& mapping) {
  auto names = dram_mapping_names();
  return std::find(names.begin(), names.end(), mapping) != names.end();
}

bool power_of_two(uint64_t x) {
  return x && !(x & (x - 1));
}

}  // namespace

std::string dram_mapping_problem(const BankedDramConfig& c) {
  if (c.mapping == "xor" && !(power_of_two(c.bank_groups) && power_of_two(c.banks_per_group)))
    return "mapping 'xor' needs power-of-two bank_groups and banks_per_group";
  if (is_named(c.mapping)) return {};
  std::vector<std::string> parts = split(c.mapping);
  std::string missing;
  for (const char* field : kFieldNames) {
    auto n = std::count(parts.begin(), parts.end(), field);
    if (n > 1) return "mapping '" + c.mapping + "' names '" + field + "' twice";
    if (n == 0) missing += (missing.empty() ? "" : ", ") + std::string(field);
  }
  if (!missing.empty())
    return "mapping '" + c.mapping + "' does not cover the address: it leaves out " + missing +
           " (a field order is row, rank, bankgroup, bank, column and channel joined by ':'; or "
           "row_bank_column_channel, interleave, xor)";
  if (parts.size() != 6)
    return "mapping '" + c.mapping +
           "' has a field that is not one of row, rank, bankgroup, "
           "bank, column, channel";
  return {};
}

DramAddressMap::DramAddressMap(const BankedDramConfig& c)
    : burst_shift_(uint32_t(__builtin_ctz(c.burst_bytes()))),
      hashed_(c.mapping == "xor"),
      banks_(c.banks_per_group),
      groups_(c.bank_groups),
      channels_(c.channels) {
  uint32_t columns = c.row_bytes / c.burst_bytes();
  auto size = [&](Field f) {
    switch (f) {
      case Field::Row: return c.rows;
      case Field::Rank: return c.ranks;
      case Field::Group: return c.bank_groups;
      case Field::Bank: return c.banks_per_group;
      case Field::Column: return columns;
      case Field::ColumnHigh: return columns / column_low_;
      case Field::Channel: return c.channels;
    }
    return 1u;
  };
  std::vector<Field> order;  // least significant first
  if (c.mapping == "row_bank_column_channel") {
    order = {Field::Channel, Field::Column, Field::Bank, Field::Group, Field::Rank, Field::Row};
  } else if (is_named(c.mapping)) {  // interleave, xor
    column_low_ = c.interleave_bytes / c.burst_bytes();
    order = {Field::Column, Field::Channel,    Field::Group, Field::Bank,
             Field::Rank,   Field::ColumnHigh, Field::Row};
  } else {
    std::vector<std::string> parts = split(c.mapping);
    for (auto it = parts.rbegin(); it != parts.rend(); ++it) {
      auto i = std::find(std::begin(kFieldNames), std::end(kFieldNames), *it) - kFieldNames;
      const Field fields[] = {Field::Row,  Field::Rank,   Field::Group,
                              Field::Bank, Field::Column, Field::Channel};
      order.push_back(fields[i]);
    }
  }
  auto member = [](Field f) -> uint32_t DramAddress::* {
    switch (f) {
      case Field::Row: return &DramAddress::row;
      case Field::Rank: return &DramAddress::rank;
      case Field::Group: return &DramAddress::group;
      case Field::Bank: return &DramAddress::bank;
      case Field::Column:
      case Field::ColumnHigh: return &DramAddress::column;
      case Field::Channel: return &DramAddress::channel;
    }
    return &DramAddress::row;
  };
  for (Field f : order) {
    uint32_t n = f == Field::Column && column_low_ > 1 ? column_low_ : size(f);
    digits_.push_back({member(f), n, f == Field::ColumnHigh ? column_low_ : 1,
                       power_of_two(n) ? uint32_t(__builtin_ctz(n)) : kNoShift});
  }
}

DramAddress DramAddressMap::decode_burst(uint64_t rest) const {
  DramAddress a;  // all 0: each digit adds to its field (the column has two)
  // The most significant digit wraps: the rest is dropped. A power-of-two digit (the usual case)
  // is a mask and a shift: a 64-bit division costs the host tens of cycles.
  for (const Digit& d : digits_) {
    uint64_t digit;
    if (d.shift != kNoShift) {
      digit = rest & (d.size - 1);
      rest >>= d.shift;
    } else {
      digit = rest % d.size;
      rest /= d.size;
    }
    a.*d.field += uint32_t(digit) * d.scale;
  }
  if (hashed_) {
    a.bank ^= a.row & (banks_ - 1);
    a.group ^= (a.row / banks_) & (groups_ - 1);
    a.channel = uint32_t((a.channel + a.row) % channels_);
  }
  return a;
}

}  // namespace rtsim
