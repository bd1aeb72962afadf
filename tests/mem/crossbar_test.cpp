// The crossbar and its links alone: latency, per-port bandwidth, contention at a shared
// destination, and bookings made out of time order.
#include <gtest/gtest.h>

#include "model/mem/crossbar.h"

namespace rtsim {
namespace {

TEST(Link, NTransfersOfALineTakeNTimesLineOverBandwidth) {
  Link link(32.0);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(link.transfer(100, 128), 103u + 4 * i);
  EXPECT_EQ(link.stats().stall_cycles, 4u + 8 + 12);
  EXPECT_EQ(link.transfer(200, 16), 200u) << "an idle link passes a small transfer in its cycle";
  EXPECT_EQ(link.transfer(200, 16), 200u) << "two share the cycle";
  EXPECT_EQ(link.transfer(200, 16), 201u);
}

TEST(Link, AnEarlierDatedTransferIsNotDelayedByALaterOneBookedFirst) {
  Link link(32.0);
  EXPECT_EQ(link.transfer(500, 128), 503u);
  EXPECT_EQ(link.transfer(100, 128), 103u) << "booked later, dated earlier: unaffected";
  EXPECT_EQ(link.transfer(499, 64), 504u) << "overlapping cycles are shared, in booking order";
}

TEST(Link, WithoutALimitTransfersTakeNoTime) {
  Link link(0);
  EXPECT_EQ(link.transfer(7, 4096), 7u);
  EXPECT_EQ(link.stats().bytes, 4096u);
}

TEST(Crossbar, AnUnloadedTransferTakesTheLatency) {
  Crossbar xbar({5, 32.0}, 2);
  xbar.add_units(1);
  EXPECT_EQ(xbar.to_slice(0, 1, 100, 8), 105u);
  EXPECT_EQ(xbar.to_unit(1, 0, 200, 32), 205u);
  EXPECT_EQ(xbar.units(), 1u);
}

TEST(Crossbar, TransfersToOneDestinationShareItsPort) {
  Crossbar xbar({2, 32.0}, 2);
  xbar.add_units(2);
  // Two slices send a 128-byte line each to unit 0 in the same cycle: their own ports are free,
  // the unit's is not.
  EXPECT_EQ(xbar.to_unit(0, 0, 100, 128), 100u + 3 + 2 + 3);
  EXPECT_EQ(xbar.to_unit(1, 0, 100, 128), 100u + 3 + 2 + 3 + 4) << "4 cycles behind";
  EXPECT_EQ(xbar.to_unit(1, 1, 100, 128), 100u + 3 + 4 + 2 + 3) << "behind at slice 1's port";
  EXPECT_EQ(xbar.unit_down(0).stats().stall_cycles, 4u);
}

TEST(Crossbar, RejectsANegativeBandwidth) {
  EXPECT_NE(crossbar_config_problem({1, -1.0}), "");
  EXPECT_THROW(Crossbar({1, -1.0}, 1), std::invalid_argument);
}

}  // namespace
}  // namespace rtsim
