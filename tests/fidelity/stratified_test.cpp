// Stratified estimates: collapsed-strata variance by hand, and ratio intervals.
#include <gtest/gtest.h>

#include <cmath>

#include "model/fidelity/stratified.h"

namespace rtsim {
namespace {

TEST(Stratified, PairsGiveTheSquaredDifferences) {
  // pairs (1, 3) and (10, 14): (1 - 3)^2 + (10 - 14)^2 = 20
  EXPECT_DOUBLE_EQ(collapsed_strata_variance({1, 3, 10, 14}), 20.0);
}

TEST(Stratified, AnOddCountEndsWithATriple) {
  // pair (2, 4): 4; triple (1, 2, 3): 3/2 * 2 = 3
  EXPECT_DOUBLE_EQ(collapsed_strata_variance({2, 4, 1, 2, 3}), 7.0);
  EXPECT_DOUBLE_EQ(collapsed_strata_variance({5}), 0.0) << "one stratum: no variance estimate";
}

TEST(Stratified, TotalsAddTheOffsetAndHaveA95PercentInterval) {
  Estimate e = total_estimate({1, 3, 10, 14}, 100);
  EXPECT_DOUBLE_EQ(e.value, 128.0);
  EXPECT_NEAR(e.ci95, 1.96 * std::sqrt(20.0), 1e-12);
}

TEST(Stratified, EqualRatiosHaveNoVariance) {
  Estimate r = ratio_estimate({2, 4, 6, 8}, {1, 2, 3, 4});
  EXPECT_DOUBLE_EQ(r.value, 2.0);
  EXPECT_NEAR(r.ci95, 0.0, 1e-12) << "y = 2x in every stratum";
  EXPECT_FALSE(ratio_estimate({1, 2}, {0, 0}).known) << "no denominator, no estimate";
  EXPECT_DOUBLE_EQ(ratio_estimate({2, 4}, {1, 2}, 4, 1).value, 2.5) << "(6 + 4) / (3 + 1)";
}

}  // namespace
}  // namespace rtsim
