#include "model/mem/dram_device.h"

#include <algorithm>
#include <numeric>

namespace rtsim {
namespace {

void at_least(DramClock& clock, DramClock value) {
  clock = std::max(clock, value);
}

}  // namespace

DramChannel::DramChannel(const BankedDramConfig& config)
    : config_(config),
      banks_(size_t(config.ranks) * config.banks()),
      groups_(size_t(config.ranks) * config.bank_groups, Next{}),
      ranks_(config.ranks),
      bank_busy_(banks_.size(), 0) {}

bool DramChannel::any_open(uint32_t rank) const {
  auto first = banks_.begin() + long(size_t(rank) * config_.banks());
  return std::any_of(first, first + config_.banks(),
                     [](const Bank& b) { return b.row != kClosed; });
}

DramClock DramChannel::earliest(DramCommand command, const DramAddress& a, DramClock now) const {
  const DramTiming& t = config_.timing;
  auto c = size_t(command);
  const Rank& rank = ranks_[a.rank];
  DramClock at =
      std::max({now, command_bus_, bank(a).next[c], groups_[group_index(a)][c], rank.next[c]});
  switch (command) {
    case DramCommand::Act:
      if (rank.act_count >= 4) at_least(at, rank.acts[rank.act_count % 4] + t.tFAW);
      break;
    case DramCommand::Rd:
    case DramCommand::Wr: {
      DramClock bus = data_free_ + (a.rank != data_rank_ && data_free_ > 0 ? t.tRTRS : 0);
      uint32_t latency = command == DramCommand::Rd ? t.tCL : t.tCWL;
      if (bus > latency) at_least(at, bus - latency);
      break;
    }
    case DramCommand::Ref: {  // every bank of the rank ready for an ACT (precharged)
      auto first = banks_.begin() + long(size_t(a.rank) * config_.banks());
      for (auto b = first; b != first + config_.banks(); ++b)
        at_least(at, b->next[size_t(DramCommand::Act)]);
      break;
    }
    case DramCommand::RefPb: at_least(at, bank(a).next[size_t(DramCommand::Act)]); break;
    default: break;
  }
  return at;
}

DramClock DramChannel::book_data(const DramAddress& a, DramClock begin) {
  DramClock burst = config_.burst_clocks();
  data_free_ = begin + burst;
  data_rank_ = a.rank;
  bank_busy_[bank_index(a)] += burst;
  return data_free_;
}

DramClock DramChannel::data_busy() const {
  return std::accumulate(bank_busy_.begin(), bank_busy_.end(), DramClock(0));
}

DramClock DramChannel::issue(DramCommand command, const DramAddress& a, DramClock at,
                             bool auto_precharge) {
  const DramTiming& t = config_.timing;
  constexpr auto kAct = size_t(DramCommand::Act), kPre = size_t(DramCommand::Pre),
                 kRd = size_t(DramCommand::Rd), kWr = size_t(DramCommand::Wr),
                 kRefPb = size_t(DramCommand::RefPb), kRef = size_t(DramCommand::Ref);
  Bank& b = banks_[bank_index(a)];
  Next& group = groups_[group_index(a)];
  Rank& rank = ranks_[a.rank];
  command_bus_ = at + 1;
  DramClock data_end = 0;
  switch (command) {
    case DramCommand::Act:
      b.row = a.row;
      at_least(b.next[kRd], at + t.tRCD_RD);
      at_least(b.next[kWr], at + t.tRCD_WR);
      at_least(b.next[kPre], at + t.tRAS);
      at_least(b.next[kAct], at + t.tRC);
      at_least(group[kAct], at + t.tRRD_L);
      at_least(rank.next[kAct], at + t.tRRD_S);
      rank.acts[rank.act_count++ % 4] = at;
      break;
    case DramCommand::Pre:
      b.row = kClosed;
      at_least(b.next[kAct], at + t.tRP);
      break;
    case DramCommand::Rd:
      at_least(group[kRd], at + t.tCCD_L);
      at_least(rank.next[kRd], at + t.tCCD_S);
      at_least(rank.next[kWr], at + t.tRTW);
      at_least(b.next[kPre], at + t.tRTP);
      data_end = book_data(a, at + t.tCL);
      break;
    case DramCommand::Wr:
      at_least(group[kWr], at + t.tCCD_L);
      at_least(rank.next[kWr], at + t.tCCD_S);
      data_end = book_data(a, at + t.tCWL);
      at_least(group[kRd], data_end + t.tWTR_L);
      at_least(rank.next[kRd], data_end + t.tWTR_S);
      at_least(b.next[kPre], data_end + t.tWR);
      break;
    case DramCommand::Ref: {
      auto first = banks_.begin() + long(size_t(a.rank) * config_.banks());
      for (auto other = first; other != first + config_.banks(); ++other)
        at_least(other->next[kAct], at + t.tRFC);
      at_least(rank.next[kRef], at + t.tRFC);
      break;
    }
    case DramCommand::RefPb:
      at_least(b.next[kAct], at + t.tRFCpb);
      at_least(b.next[kRefPb], at + t.tRFCpb);
      break;
    case DramCommand::kCount: break;
  }
  if (auto_precharge && (command == DramCommand::Rd || command == DramCommand::Wr)) {
    b.row = kClosed;  // the implied PRE, as soon as tRAS, tRTP or tWR allow
    at_least(b.next[kAct], std::max(b.next[kPre], at) + t.tRP);
  }
  return data_end;
}

}  // namespace rtsim
