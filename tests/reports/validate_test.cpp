// rtsim validate: the quick suite passes on the defaults and on every preset's machine, a model
// broken on purpose (a latency or rate other than the configured one) fails the check that
// measures it, and the pages agree with the JSON.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <regex>

#include "reports/validate/checks.h"
#include "reports/validate/suite.h"
#include "tests/cli/run_rtsim.h"
#include "tests/temp_dir.h"

namespace rtsim::validation {
namespace {

std::map<std::string, Check> by_id(const SuiteResult& r) {
  std::map<std::string, Check> out;
  for (const Check& c : r.checks) out[c.id] = c;
  return out;
}

SuiteResult quick(const std::function<void(HwConfig&)>& tamper) {
  return run_suite({HwConfig{}, tamper}, true, [](const std::string&) {});
}

TEST(Validate, QuickSuitePassesOnTheDefaults) {
  SuiteResult r = quick({});
  EXPECT_EQ(r.failed(), 0u) << terminal_table(r);
  std::map<std::string, Check> c = by_id(r);
  EXPECT_EQ(r.skipped(), 3u) << "the defaults set no L1, L2 or crossbar bandwidth";
  EXPECT_FALSE(c["roofline.l2_port"].ran());
  // The defaults' sums: dispatch 8 + setup 4 + box 8 + triangle 12 + 2 x control 1 = 34.
  EXPECT_EQ(c["ladder.l1_hit"].measured, 34 + 2 * 20);
  EXPECT_EQ(c["ladder.l2_hit"].measured, 34 + 2 * (20 + 80));
  EXPECT_GE(c["roofline.dram"].measured, 0.9 * 256 / 1.5);
}

TEST(Validate, QuickSuitePassesOnEveryPreset) {
  for (const auto& entry : std::filesystem::directory_iterator(RTSIM_SOURCE_DIR "/configs")) {
    if (entry.path().extension() != ".toml") continue;
    // xe-hpg's old name, the same machine (HwConfig.ArcA770IsAnAliasOfXeHpg): checked once.
    if (entry.path().stem() == "arc-a770") continue;
    HwConfig config = load_hw_config(entry.path().string());
    SuiteResult r = run_suite({config, {}}, true, [](const std::string&) {});
    EXPECT_EQ(r.failed(), 0u) << entry.path() << "\n" << terminal_table(r);
  }
}

// A rung per cache level of a four-level machine (a group level, a sliced one and a victim last
// level), each exact; a level whose latency the model gets wrong fails its own rung only.
TEST(Validate, EachLevelOfAFourLevelHierarchyHasAnExactRung) {
  HwConfig four = load_hw_config(RTSIM_SOURCE_DIR "/configs/examples/four-levels.toml");
  std::map<std::string, Check> c = by_id(run_suite({four, {}}, true, [](const std::string&) {}));
  for (const char* rung : {"ladder.l0_hit", "ladder.l1_hit", "ladder.l2_hit", "ladder.ic_hit"})
    EXPECT_TRUE(c[rung].passed()) << rung << ": " << c[rung].measured << " against "
                                  << c[rung].expected;
  auto slower_ic = [](HwConfig& h) { h.memory[3].cache.hit_latency += 5; };
  c = by_id(run_suite({four, slower_ic}, true, [](const std::string&) {}));
  EXPECT_TRUE(c["ladder.l2_hit"].passed());
  EXPECT_EQ(c["ladder.ic_hit"].measured, c["ladder.ic_hit"].expected + 2 * 5);
}

TEST(Validate, ALatencyOtherThanTheConfiguredOneFailsItsRung) {
  SuiteResult r = quick([](HwConfig& c) { last_level(c).cache.hit_latency += 3; });
  std::map<std::string, Check> c = by_id(r);
  EXPECT_TRUE(c["ladder.l1_hit"].passed());
  EXPECT_FALSE(c["ladder.l2_hit"].passed());
  EXPECT_EQ(c["ladder.l2_hit"].measured, c["ladder.l2_hit"].expected + 2 * 3);
  r = quick([](HwConfig& c) {
    c.banked_dram.timing.tRP += 4;
    c.banked_dram.timing.tRC += 4;
  });
  c = by_id(r);
  EXPECT_TRUE(c["ladder.dram_closed"].passed());
  EXPECT_TRUE(c["ladder.dram_row_hit"].passed());
  EXPECT_FALSE(c["ladder.dram_conflict"].passed()) << "tRP is only in the conflict's sum";
  EXPECT_EQ(r.failed(), 1u) << terminal_table(r);
}

TEST(Validate, ARateOtherThanTheConfiguredOneFailsItsCeiling) {
  SuiteResult r = quick([](HwConfig& c) {
    if (c.rt.issue_per_cycle == 2) c.rt.issue_per_cycle = 1;  // not the ceilings' unlimited 64
  });
  std::map<std::string, Check> c = by_id(r);
  EXPECT_FALSE(c["ceiling.issue_slots"].passed());
  EXPECT_NEAR(c["ceiling.issue_slots"].measured, 1.0, 0.02);
  r = quick([](HwConfig& c) { c.banked_dram.channels /= 2; });
  c = by_id(r);
  EXPECT_FALSE(c["roofline.dram"].passed());
  EXPECT_LT(c["roofline.dram"].measured, 0.51 * c["roofline.dram"].expected);
}

// The box and triangle ceilings count tests, not issues: count x issue_width as vendors publish
// them, so a pool that ignored issue_width fails them.
std::map<std::string, Check> ceilings(const HwConfig& config, bool ignore_width) {
  std::function<void(HwConfig&)> tamper;
  if (ignore_width)
    tamper = [](HwConfig& c) { c.rt.box.issue_width = c.rt.triangle.issue_width = 1; };
  std::map<std::string, Check> out;
  for (const Check& c : throughput_ceilings({config, tamper})) out[c.id] = c;
  return out;
}

TEST(Validate, CeilingsCountTestsSoAnIgnoredIssueWidthFails) {
  HwConfig xe_hpg;  // 12 box and 1 triangle tests a clock: 2 pipelines of a 6-wide node
  xe_hpg.rt.box = {2, 6, 8};
  xe_hpg.rt.triangle = {1, 1, 12};
  std::map<std::string, Check> c = ceilings(xe_hpg, false);
  EXPECT_TRUE(c["ceiling.box_tests"].passed()) << c["ceiling.box_tests"].measured;
  EXPECT_EQ(c["ceiling.box_tests"].expected, 12);
  EXPECT_TRUE(c["ceiling.triangle_tests"].passed()) << c["ceiling.triangle_tests"].measured;
  c = ceilings(xe_hpg, true);
  EXPECT_FALSE(c["ceiling.box_tests"].passed());
  EXPECT_NEAR(c["ceiling.box_tests"].measured, 2.0, 0.04) << "two issues of one box a cycle";

  HwConfig rdna4;  // one issue a clock: 8 box or 2 triangle tests
  rdna4.rt.test_issue = TestIssue::Shared;
  rdna4.rt.box = {1, 8, 8};
  rdna4.rt.triangle = {1, 2, 12};
  c = ceilings(rdna4, false);
  EXPECT_TRUE(c["ceiling.box_tests"].passed()) << c["ceiling.box_tests"].measured;
  EXPECT_TRUE(c["ceiling.triangle_tests"].passed()) << c["ceiling.triangle_tests"].measured;
  EXPECT_EQ(c["ceiling.triangle_tests"].expected, 2);
  c = ceilings(rdna4, true);
  EXPECT_FALSE(c["ceiling.box_tests"].passed());
  EXPECT_FALSE(c["ceiling.triangle_tests"].passed());
  EXPECT_NEAR(c["ceiling.triangle_tests"].measured, 1.0, 0.02) << "one triangle an issue";
}

TEST(Validate, PagesShowFailuresSkipsAndReportedFigures) {
  SuiteResult r;
  r.config_name = "x";
  Check fail{"a.fail", "closed_form", "fails", "formula: 1"};
  set_exact(fail, 1);
  fail.measured = 2;
  fail.look_at = "type.*.nodes";
  Check skip{"a.skip", "closed_form", "skips"};
  skip.skipped = "nothing to check";
  Check info{"a.info", "sensitivity", "reports"};
  info.measured = 0.5;
  r.checks = {fail, skip, info};
  EXPECT_EQ(r.failed(), 1u);
  EXPECT_EQ(r.skipped(), 1u);
  EXPECT_EQ(r.reported(), 1u);
  EXPECT_STREQ(r.checks[2].status(), "info");
  std::string junit = junit_xml(r);
  EXPECT_NE(junit.find("failures='1' skipped='1'"), std::string::npos) << junit;
  EXPECT_NE(junit.find("<failure message='measured 2 , expected = 1'>"), std::string::npos)
      << junit;
  EXPECT_NE(junit.find("<skipped message='nothing to check'/>"), std::string::npos);
  EXPECT_NE(terminal_table(r).find("FAIL a.fail: measured 2"), std::string::npos);
  EXPECT_NE(markdown_page(r).find("look at: type.\\*.nodes"), std::string::npos);
  EXPECT_NE(html_page(r).find("<td class='fail'>fail</td>"), std::string::npos);
  EXPECT_EQ(suite_json(r)["checks"][2]["status"], "info");
}

TEST(ValidateCli, WritesPagesThatAgreeWithTheJsonAndRefusesBadInput) {
  test::TempDir dir;
  std::string out = dir.path("out");
  test::RunResult run = test::run_rtsim(
      "validate --quick --config " RTSIM_SOURCE_DIR "/configs/mobile.toml -o " + out);
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("passed, 0 failed"), std::string::npos) << run.out;
  auto doc = nlohmann::json::parse(test::slurp(out + "/validate.json"));
  EXPECT_EQ(doc["schema"], kValidateSchema);
  EXPECT_EQ(doc["config"], "mobile");
  std::string html = test::slurp(out + "/validate.html");
  std::regex cell("data-key=\"checks\\.([0-9]+)\\.([a-z]+)\" data-value=\"([^\"]*)\"");
  size_t cells = 0;
  for (std::sregex_iterator it(html.begin(), html.end(), cell), end; it != end; ++it, ++cells) {
    const auto& value = doc["checks"][std::stoul((*it)[1])][(*it)[2].str()];
    if ((*it)[3] == "null")
      EXPECT_TRUE(value.is_null()) << (*it)[0];
    else
      EXPECT_EQ(std::stod((*it)[3]), value.get<double>()) << (*it)[0];
  }
  EXPECT_EQ(cells, 4 * doc["checks"].size());
  EXPECT_NE(html.find("<title>Measured against the pass band, suite closed_form</title>"),
            std::string::npos);
  EXPECT_EQ(html.find("src='http"), std::string::npos) << "opens offline";
  std::string junit = test::slurp(out + "/junit.xml");
  size_t cases = 0;
  for (size_t at = 0; (at = junit.find("<testcase ", at)) != std::string::npos; ++at) ++cases;
  EXPECT_EQ(cases, doc["checks"].size());
  EXPECT_NE(test::slurp(out + "/validate.md").find("| ladder.l1_hit"), std::string::npos);

  run = test::run_rtsim("validate --quick --set dram.channels=1 --set rt.warps=1");
  EXPECT_EQ(run.exit_code, 0) << "a valid config passes: the checks expect what it configures";
  run = test::run_rtsim("validate --quick --config /nonexistent.toml");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("/nonexistent.toml"), std::string::npos) << run.err;
}

// --only runs the groups whose checks it names and keeps those checks; a prefix no check has is
// refused, naming the ones there are.
TEST(Validate, OnlyRunsTheChecksItNames) {
  std::vector<std::string> heard;
  SuiteResult r =
      run_suite({HwConfig{}, {}}, false, [&](const std::string& g) { heard.push_back(g); },
                {"ladder.l1", "ceiling.box"});
  EXPECT_EQ(heard, (std::vector<std::string>{"latency ladder", "throughput ceilings"}));
  std::vector<std::string> ids;
  for (const Check& c : r.checks) ids.push_back(c.id);
  EXPECT_EQ(ids, (std::vector<std::string>{"ladder.l1_hit", "ceiling.box_tests"}));
  EXPECT_EQ(only_problem({"vendor"}), "");
  EXPECT_EQ(only_problem({"vendor.rtx2080ti.bunny"}), "");
  std::string problem = only_problem({"ladder", "nosuch"});
  EXPECT_NE(problem.find("--only nosuch: no check's id starts with it"), std::string::npos)
      << problem;
  EXPECT_NE(problem.find("vendor."), std::string::npos) << problem;
  test::RunResult run = test::run_rtsim("validate --only nosuch");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--only nosuch"), std::string::npos) << run.err;
}

// The vendor check judges the config under test at its own clock: a config without a vendor
// rate is skipped, and the RTX 2080 Ti preset as it was before it was sourced (fp32 256-byte
// nodes; tests/fixtures/rtx2080ti-before.toml) reads below the band NVIDIA's figure supports.
TEST(Validate, VendorCheckFailsTheOldRtx2080ti) {
  auto vendor = [](const HwConfig& config) {
    return by_id(run_suite({config, {}}, false, [](const std::string&) {}, {"vendor"}));
  };
  std::map<std::string, Check> c = vendor(HwConfig{});
  ASSERT_EQ(c.size(), 2u);
  EXPECT_FALSE(c.begin()->second.ran()) << c.begin()->second.id;
  if (!std::filesystem::exists(shared_scene_path("bunny")))
    GTEST_SKIP() << "the shared scenes are missing";
  HwConfig before = load_hw_config(RTSIM_SOURCE_DIR "/tests/fixtures/rtx2080ti-before.toml");
  ASSERT_EQ(before.name, "rtx2080ti");
  c = vendor(before);
  const Check& bunny = c["vendor.rtx2080ti.bunny"];
  ASSERT_TRUE(bunny.ran()) << bunny.skipped;
  EXPECT_NEAR(bunny.expected, 10e9 / (68 * before.clock_ghz * 1e9), 1e-12) << "at its own clock";
  EXPECT_TRUE(bunny.failed()) << bunny.measured << " in " << bunny.lo << ".." << bunny.hi;
  EXPECT_LT(bunny.measured, bunny.lo);
  EXPECT_NE(bunny.detail.find("l1 port"), std::string::npos) << bunny.detail;
}

}  // namespace
}  // namespace rtsim::validation
