// `rtsim compare`: runs, sim folders and sweep points side by side; every ratio is the JSON's
// values divided, every number on the page is the JSON's; a categorical sweep key charts as bars.
#include <gtest/gtest.h>

#include <filesystem>

#include <fmt/core.h>

#include "reports/metrics.h"
#include "tests/reports/report_test_util.h"
#include "traces/error.h"

namespace rtsim {
namespace {

using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;

// Two runs of one stream (4 and 2 RT units), a sim of it, and a sweep over node formats.
class Compare : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = test::fresh_dir("compare");
    std::string config = " --config " + test::source_path("configs/mobile.toml");
    ASSERT_EQ(test::run_rtsim("trace pica --resolution 32x18 -o " + dir_ + "/pica.rays").exit_code,
              0);
    for (auto [name, set] : {std::pair{"four", ""}, {"two", " --set rt.count=2"}})
      ASSERT_EQ(test::run_rtsim("run " + dir_ + "/pica.rays" + config + set +
                                " --report json -q -o " + dir_ + "/" + name)
                    .exit_code,
                0);
    ASSERT_EQ(test::run_rtsim("sim " + dir_ + "/pica.rays" + config + " -q -o " + dir_ + "/sim")
                  .exit_code,
              0);
  }
  static std::string dir_;
};
std::string Compare::dir_;

TEST(CompareMetrics, TypeWildcardsExpandOverTheRunsTypesAndUnknownNamesAreRefused) {
  Json a = {{"workload", {{"rays_per_type", {{"camera", 10}, {"shadow", 5}}}}}};
  Json b = {{"workload", {{"rays_per_type", {{"camera", 10}, {"ao", 2}}}}}};
  std::vector<std::string> names =
      reports::expand_metric_names({"cycles", "type.*.l1_hit_rate"}, {a, b}, "--metric");
  EXPECT_EQ(names, (std::vector<std::string>{"cycles", "type.camera.l1_hit_rate",
                                             "type.shadow.l1_hit_rate", "type.ao.l1_hit_rate"}));
  try {
    reports::expand_metric_names({"type.*.l1_hit_rat"}, {a}, "--metric");
    FAIL() << "a misspelt metric must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--metric type.*.l1_hit_rat: unknown metric"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(reports::metric_style("type.ao.l2_hit_rate"), reports::Style::Percent);
  EXPECT_EQ(reports::metric_style("cycles"), reports::Style::Integer);
  EXPECT_EQ(reports::metric_style("dram_bytes_per_ray"), reports::Style::Real);
}

TEST_F(Compare, RatiosAreToTheFirstRun) {
  std::string out = dir_ + "/cmp";
  test::RunResult r =
      test::run_rtsim("compare " + dir_ + "/four " + dir_ + "/two " + dir_ +
                      "/sim --metric cycles,l2_hit_rate,type.*.nodes_per_ray -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Json doc = test::read_json(out + "/compare.json");
  ASSERT_EQ(doc["runs"].size(), 3u);
  Json a = test::read_json(dir_ + "/four/report.json"),
       b = test::read_json(dir_ + "/two/report.json");
  double ca = a["timing"]["cycles"].get<double>(), cb = b["timing"]["cycles"].get<double>();
  EXPECT_EQ(doc["runs"][1]["metrics"]["cycles"].get<double>(), cb);
  EXPECT_DOUBLE_EQ(doc["runs"][1]["ratios"]["cycles"].get<double>(), cb / ca);
  EXPECT_DOUBLE_EQ(doc["runs"][1]["speedup"].get<double>(), ca / cb);
  EXPECT_DOUBLE_EQ(doc["runs"][2]["ratios"]["cycles"].get<double>(), 1.0)
      << "the sim folder ran the first run's stream and config";
  EXPECT_TRUE(doc["runs"][0]["metrics"].contains("type.camera.nodes_per_ray"))
      << "type.*.NAME names each ray type";
  EXPECT_EQ(doc["runs"][1]["bottleneck"], b["timing"]["bottleneck"]["text"]);
  EXPECT_NE(r.out.find("B/A"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(fmt::format("{:.3f}x", cb / ca)), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("limit      B: " + b["timing"]["bottleneck"]["text"].get<std::string>()),
            std::string::npos)
      << r.out;
  std::string html = test::slurp(out + "/compare.html");
  int cells = 0;
  for (const test::Cell& c : test::number_cells(html)) {
    std::string key = c.key;
    size_t run = std::stoul(key.substr(5, key.find('.', 5) - 5));
    std::string rest = key.substr(key.find('.', 5) + 1);
    size_t dot = rest.find('.');
    const Json& at = dot == std::string::npos
                         ? doc["runs"][run][rest]
                         : doc["runs"][run][rest.substr(0, dot)][rest.substr(dot + 1)];
    EXPECT_EQ(c.value, at.dump()) << key;
    ++cells;
  }
  EXPECT_GE(cells, 3 * 3 + 2 * 3) << "values and ratios of every run";
  EXPECT_NE(test::slurp(out + "/compare.md").find("| cycles |"), std::string::npos);
}

TEST_F(Compare, BadRunsAndMetricsAreExitTwo) {
  test::RunResult r = test::run_rtsim("compare " + dir_ + "/four");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("give at least two"), std::string::npos) << r.err;
  r = test::run_rtsim("compare " + dir_ + "/four " + dir_ + "/two --metric cycels");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--metric cycels: unknown metric 'cycels'"), std::string::npos) << r.err;
  r = test::run_rtsim("compare " + dir_ + "/four " + dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("not a run, sim or sweep folder"), std::string::npos) << r.err;
}

TEST_F(Compare, ASweepComparesItsPointsAndChartsACategoricalKeyAsBars) {
  test::TempDir tmp;
  std::string spec = tmp.write(
      "formats.toml",
      "name = \"formats\"\nconfig = \"" + test::source_path("configs/mobile.toml") +
          "\"\n[[workload]]\nname = \"pica\"\nworkload = \"pica\"\nresolution = \"32x18\"\n"
          "[grid]\n\"bvh.node_format\" = [\"aabb32\", \"cwbvh8\"]\n"
          "[[chart]]\nx = \"bvh.node_format\"\ny = \"type.*.dram_bytes_per_ray\"\n");
  std::string sweep = dir_ + "/sweep";
  test::RunResult r = test::run_rtsim("sweep " + spec + " -o " + sweep + " -j 2 -q");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  Json doc = test::read_json(sweep + "/sweep.json");
  EXPECT_TRUE(doc["charts"][0]["available"].get<bool>()) << doc["charts"][0];
  EXPECT_TRUE(fs::exists(sweep + "/" + doc["charts"][0]["file"].get<std::string>()));
  r = test::run_program("RTSIM_PYTHON=/nonexistent/python3 " RTSIM_EXE, "report " + sweep);
  EXPECT_EQ(r.exit_code, 1) << "a sweep's charts that fail: " << r.out << r.err;
  EXPECT_NE(r.err.find("rtsim: charts failed: /nonexistent/python3 not found"), std::string::npos)
      << r.err;
  r = test::run_rtsim("compare " + sweep + " --metric nodes_per_ray");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("compare    2 runs"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("pica bvh.node_format=cwbvh8"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace rtsim
