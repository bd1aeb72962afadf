// The timing state of one DRAM channel: its ranks, bank groups and banks, the command bus (one
// command per clock) and the data bus. For each command and place it keeps the earliest clock
// the constraints of the commands issued so far allow (Ramulator's scheme), so earliest() is a
// handful of maxima and issue() updates the places a command constrains. Clocks are DRAM
// command clocks (tCK). The controller (dram_controller.h) decides what to issue.
// Not modelled: tRREFD between per-bank refreshes, power-down, ZQ calibration, bank-group
// modes that change tCCD with the burst length.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "model/mem/dram_address.h"
#include "model/mem/dram_config.h"

namespace rtsim {

using DramClock = uint64_t;

enum class DramCommand : uint8_t { Act, Pre, Rd, Wr, Ref, RefPb, kCount };

class DramChannel {
 public:
  explicit DramChannel(const BankedDramConfig& config);

  // The earliest clock, not before `now`, at which `command` to `a` may issue. Ref needs every
  // bank of the rank closed, RefPb and Act the bank; Rd and Wr the row open (not checked here).
  DramClock earliest(DramCommand command, const DramAddress& a, DramClock now) const;
  // Issues the command at `at` (at >= earliest). Rd and Wr with auto_precharge close the row
  // as soon as the bank allows (closed-page policy). Returns, for Rd and Wr, the clock the data
  // transfer ends.
  DramClock issue(DramCommand command, const DramAddress& a, DramClock at,
                  bool auto_precharge = false);

  static constexpr uint32_t kClosed = ~0u;
  uint32_t open_row(const DramAddress& a) const { return bank(a).row; }
  bool any_open(uint32_t rank) const;  // a row open in some bank of the rank
  // Data bus clocks per bank (index rank * banks + group * banks_per_group + bank).
  const std::vector<DramClock>& bank_busy() const { return bank_busy_; }
  DramClock data_busy() const;  // their sum: the channel's data bus

 private:
  static constexpr size_t kCommands = size_t(DramCommand::kCount);
  using Next = std::array<DramClock, kCommands>;  // per command: its earliest clock
  struct Bank {
    uint32_t row = kClosed;
    Next next{};
  };
  struct Rank {
    Next next{};
    std::array<DramClock, 4> acts{};  // the last four ACTs, for tFAW
    uint32_t act_count = 0;
  };
  size_t bank_index(const DramAddress& a) const {
    return (size_t(a.rank) * config_.bank_groups + a.group) * config_.banks_per_group + a.bank;
  }
  size_t group_index(const DramAddress& a) const {
    return size_t(a.rank) * config_.bank_groups + a.group;
  }
  const Bank& bank(const DramAddress& a) const { return banks_[bank_index(a)]; }
  // Books the data bus for a burst of bank `a` starting at `begin`; returns its end.
  DramClock book_data(const DramAddress& a, DramClock begin);

  BankedDramConfig config_;
  std::vector<Bank> banks_;
  std::vector<Next> groups_;
  std::vector<Rank> ranks_;
  DramClock command_bus_ = 0;  // earliest clock for the next command
  DramClock data_free_ = 0;    // the data bus is free from
  uint32_t data_rank_ = 0;     // the rank that used it last
  std::vector<DramClock> bank_busy_;
};

}  // namespace rtsim
