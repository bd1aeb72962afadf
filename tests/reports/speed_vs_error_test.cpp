// `rtsim speed-vs-error` on pica at a small resolution: a row per level and rate with its time,
// speed-up and errors against the full model, as a table, JSON, CSV, Markdown and a chart.
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/reports/report_test_util.h"

namespace rtsim {
namespace {

using Json = nlohmann::ordered_json;

TEST(SpeedVsError, ComparesEveryLevelWithTheFullModel) {
  std::string dir = test::fresh_dir("speed");
  test::RunResult r = test::run_rtsim("speed-vs-error pica --resolution 96x54 --config " +
                                      test::source_path("configs/mobile.toml") +
                                      " --rates 4,8 --sample-method scale-model,windows -o " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  Json doc = test::read_json(dir + "/speed_vs_error.json");
  std::vector<std::string> labels;
  for (const Json& row : doc["rows"]) labels.push_back(row["label"]);
  EXPECT_EQ(labels, (std::vector<std::string>{"cycle", "functional", "cache", "sampled 1/4",
                                              "sampled 1/8", "windows 1/4", "windows 1/8"}));
  EXPECT_EQ(doc["results"][3]["sample_method"], "scale-model");
  EXPECT_EQ(doc["results"][5]["sample_method"], "windows");
  const Json& reference = doc["rows"][0];
  EXPECT_DOUBLE_EQ(reference["cycles"]["error"].get<double>(), 0.0);
  for (const Json& row : doc["rows"]) {
    EXPECT_GT(row["cpu_seconds"].get<double>(), 0.0) << row["label"];
    EXPECT_GT(row["speedup"].get<double>(), 0.0) << row["label"];
    bool timed = row["level"] != "functional";
    EXPECT_EQ(row["cycles"].is_null(), !timed) << row["label"];
    if (timed) {
      EXPECT_TRUE(row["dram_bytes"]["error"].is_number()) << row["label"];
    }
  }
  EXPECT_GT(doc["rows"][3]["cycles"]["ci95"].get<double>(), 0.0) << "sampled: an interval";
  EXPECT_GT(doc["rows"][5]["cycles"]["ci95"].get<double>(), 0.0) << "windows: an interval";
  EXPECT_NE(r.out.find("sampled 1/8"), std::string::npos) << "the table is printed";
  EXPECT_EQ(test::count_lines(test::slurp(dir + "/speed_vs_error.csv")), 8);
  EXPECT_NE(test::slurp(dir + "/speed_vs_error.md").find("| sampled 1/4 |"), std::string::npos);
  EXPECT_EQ(test::slurp(dir + "/speed_vs_error.png").substr(1, 3), "PNG");
  std::filesystem::remove_all(dir);
}

TEST(SpeedVsError, AStreamTooShortForTheRateIsBadInput) {
  std::string dir = test::fresh_dir("speed-short");
  test::RunResult r = test::run_rtsim("speed-vs-error cornell --resolution 2x2 --config " +
                                      test::source_path("configs/mobile.toml") +
                                      " --rates 64 --no-charts -o " + dir);
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("rays.rays: 9 rays, too few to sample 1 in 64"), std::string::npos) << r.err;
  // The trace's progress lines come first; the error is one line, the last.
  size_t error = r.err.find("rtsim: error: ");
  EXPECT_EQ(r.err.find('\n', error) + 1, r.err.size()) << r.err;
  std::filesystem::remove_all(dir);
}

TEST(SpeedVsError, AChartThatFailsIsExitOneWithTheReason) {
  std::string dir = test::fresh_dir("speed-nochart");
  test::RunResult r = test::run_program("RTSIM_PYTHON=/nonexistent/python3 " RTSIM_EXE,
                                        "speed-vs-error cornell --resolution 16x9 --config mobile "
                                        "--rates 2 -o " +
                                            dir);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.err.find("rtsim: charts failed: /nonexistent/python3 not found"), std::string::npos)
      << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir + "/speed_vs_error.md")) << "the rest is written";
  EXPECT_FALSE(std::filesystem::exists(dir + "/speed_vs_error.png"));
  std::filesystem::remove_all(dir);
}

TEST(SpeedVsError, WindowOptionsNeedTheWindowsMethod) {
  test::RunResult r = test::run_rtsim("speed-vs-error cornell --window 2048 --no-charts");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("--window applies to --sample-method windows only"), std::string::npos)
      << r.err;
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  r = test::run_rtsim("run cornell --fidelity sampled --sample-method everything -o /tmp/x");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("unknown method 'everything' (scale-model, warmed, windows)"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace rtsim
