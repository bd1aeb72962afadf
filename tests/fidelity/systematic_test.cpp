// The systematic-sample estimator: totals and ratios scaled by k, and the successive-difference
// variance against values worked by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "model/fidelity/systematic.h"

namespace rtsim {
namespace {

TEST(Systematic, ConstantUnitsGiveTheTotalWithNoInterval) {
  SystematicSeries s;
  for (int i = 0; i < 10; ++i) s.add(5.0);
  Estimate t = s.total(4.0);
  EXPECT_DOUBLE_EQ(t.value, 200.0);
  EXPECT_DOUBLE_EQ(t.ci95, 0.0);
}

TEST(Systematic, IntervalFromSuccessiveDifferences) {
  SystematicSeries s;
  for (double y : {1.0, 3.0, 2.0, 4.0}) s.add(y);
  // Differences 2, -1, 2: s^2 = 9 / (2 x 3) = 1.5; V = k^2 (1 - 1/k) n s^2 = 4 x 0.5 x 4 x 1.5.
  Estimate t = s.total(2.0, 1.0);
  EXPECT_DOUBLE_EQ(t.value, 21.0) << "2 x 10, plus the offset";
  EXPECT_NEAR(t.ci95, 1.96 * std::sqrt(12.0), 1e-12);
}

TEST(Systematic, WholePopulationHasNoSamplingError) {
  SystematicSeries s;
  for (double y : {1.0, 7.0, 2.0}) s.add(y);
  EXPECT_DOUBLE_EQ(s.total(1.0).ci95, 0.0);
}

TEST(Systematic, ProportionalUnitsGiveAnExactRatio) {
  SystematicSeries s;
  for (double x : {3.0, 10.0, 1.0, 6.0}) s.add(2.0 * x, x);
  Estimate r = s.ratio(8.0);
  EXPECT_DOUBLE_EQ(r.value, 2.0);
  EXPECT_NEAR(r.ci95, 0.0, 1e-12) << "y - 2x is 0 in every unit";
}

TEST(Systematic, RatioOffsetsAreAddedAfterScaling) {
  SystematicSeries s;
  s.add(1.0, 2.0);
  s.add(1.0, 2.0);
  EXPECT_DOUBLE_EQ(s.ratio(3.0, 2.0, 0.0).value, (3.0 * 2 + 2.0) / (3.0 * 4));
  EXPECT_FALSE(SystematicSeries().ratio(2.0).known) << "no denominator";
}

}  // namespace
}  // namespace rtsim
