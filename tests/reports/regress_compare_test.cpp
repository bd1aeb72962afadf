// The comparison with a baseline: tolerances, directions, missing metrics, verification and
// cases without a baseline; and the JUnit XML's counts.
#include <gtest/gtest.h>

#include "reports/regress_compare.h"

namespace rtsim::reports {
namespace {

using Json = nlohmann::ordered_json;

RegressSuite suite() {
  RegressSuite s;
  s.name = "unit";
  s.cases.push_back({});
  s.tolerances = {{"cycles", 0.02, 0, ""},
                  {"l1_hit_rate", 0, 0.01, ""},
                  {"rays", 0, 0, ""},
                  {"type.*.latency_p50", 0.1, 0, ""}};
  return s;
}

CaseOutcome outcome(double cycles, double l1, double unexplained = 0) {
  return {"a", true, 0,
          Json{{"cycles", cycles},
               {"l1_hit_rate", l1},
               {"rays", 100},
               {"unexplained", unexplained},
               {"type.camera.latency_p50", 50}},
          1.0};
}

Json baseline() {
  return baseline_json(suite(), {outcome(1000, 0.8)});
}

std::string status_of(const RegressResult& r, const std::string& metric) {
  for (const MetricCheck& c : r.checks)
    if (c.metric == metric) return c.status;
  return "absent";
}

TEST(RegressCompare, WithinToleranceIsOk) {
  RegressResult r = compare_with_baseline(suite(), {outcome(1019, 0.791)}, baseline());
  EXPECT_FALSE(r.failed());
  EXPECT_EQ(status_of(r, "cycles"), "ok");
  EXPECT_EQ(status_of(r, "type.camera.latency_p50"), "ok") << "wildcards cover every ray type";
}

TEST(RegressCompare, WorseBeyondToleranceRegressesBetterImproves) {
  RegressResult slower = compare_with_baseline(suite(), {outcome(1030, 0.8)}, baseline());
  EXPECT_EQ(status_of(slower, "cycles"), "regressed");
  EXPECT_TRUE(slower.failed());
  RegressResult faster = compare_with_baseline(suite(), {outcome(900, 0.85)}, baseline());
  EXPECT_EQ(status_of(faster, "cycles"), "improved");
  EXPECT_EQ(status_of(faster, "l1_hit_rate"), "improved") << "a higher hit rate is better";
  EXPECT_FALSE(faster.failed());
}

TEST(RegressCompare, AnyChangeOfANeutralMetricFails) {
  CaseOutcome c = outcome(1000, 0.8);
  c.metrics["rays"] = 101;
  RegressResult r = compare_with_baseline(suite(), {c}, baseline());
  EXPECT_EQ(status_of(r, "rays"), "changed");
  EXPECT_TRUE(r.failed());
}

TEST(RegressCompare, VerificationFailuresAndUnknownCasesFail) {
  RegressResult r = compare_with_baseline(suite(), {outcome(1000, 0.8, 3)}, baseline());
  EXPECT_TRUE(r.failed());
  ASSERT_EQ(r.case_failures.size(), 1u);
  EXPECT_NE(r.case_failures[0].find("3 unexplained"), std::string::npos);
  CaseOutcome other = outcome(1000, 0.8);
  other.name = "new";
  EXPECT_TRUE(compare_with_baseline(suite(), {other}, baseline()).failed());
}

TEST(RegressCompare, JunitCountsTestsAndFailures) {
  RegressResult r = compare_with_baseline(suite(), {outcome(1030, 0.8)}, baseline());
  std::string xml = junit_xml(suite(), r);
  EXPECT_NE(xml.find("tests=\"5\" failures=\"1\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("<failure message=\"regressed"), std::string::npos) << xml;
}

}  // namespace
}  // namespace rtsim::reports
