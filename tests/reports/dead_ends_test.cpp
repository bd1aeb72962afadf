// No dead ends (issue 66, item 4): a ray stream is a workload of `rtsim run`, a `rtsim sim` folder
// gets a report from `rtsim report`, the report of either is the one `rtsim run` writes from the
// same inputs, and a chart that fails makes the command exit 1 with the reason.
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/reports/report_test_util.h"

namespace rtsim {
namespace {

using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;

std::string mobile() {
  return " --config " + test::source_path("configs/mobile.toml");
}

// One traced stream, a run of it and a sim of it, shared by the tests of this file.
class StreamRuns : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = test::fresh_dir("dead-ends");
    test::RunResult t = test::run_rtsim("trace pica --resolution 32x18 -o " + dir_ + "/pica.rays");
    ASSERT_EQ(t.exit_code, 0) << t.err;
    test::RunResult run = test::run_rtsim("run " + dir_ + "/pica.rays" + mobile() + " -o " + dir_ +
                                          "/run -q --no-charts");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    test::RunResult sim =
        test::run_rtsim("sim " + dir_ + "/pica.rays" + mobile() + " -o " + dir_ + "/sim -q");
    ASSERT_EQ(sim.exit_code, 0) << sim.err;
  }
  static std::string dir_;
};
std::string StreamRuns::dir_;

TEST_F(StreamRuns, RunTakesAStreamAsItsWorkload) {
  Json report = test::read_json(dir_ + "/run/report.json");
  Json stats = test::read_json(dir_ + "/sim/stats.json");
  EXPECT_EQ(report["workload"]["name"], "pica");
  EXPECT_EQ(report["workload"]["width"], 32);
  EXPECT_EQ(report["timing"]["rays"], stats["summary"]["rays"]);
  EXPECT_EQ(report["timing"]["cycles"], stats["summary"]["cycles"])
      << "the same stream on the same config: the same cycles as rtsim sim";
  EXPECT_TRUE(report["workload"]["passes"].empty()) << "a stream records no passes";
  EXPECT_NE(test::slurp(dir_ + "/run/report.html").find("Passes not recorded"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ + "/run/trace")) << "the stream is not traced again";
}

TEST_F(StreamRuns, FromTraceTakesAStreamToo) {
  std::string out = dir_ + "/from-trace";
  test::RunResult r = test::run_rtsim("run --from-trace " + dir_ + "/pica.rays" + mobile() +
                                      " --set rt.count=2 --report json -q -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Json report = test::read_json(out + "/report.json");
  EXPECT_EQ(report["hardware"]["rt_units"], 2);
  EXPECT_EQ(report["timing"]["rays"], test::read_json(dir_ + "/sim/stats.json")["summary"]["rays"]);
}

TEST_F(StreamRuns, AStreamCannotBeRetracedOrGivenTwice) {
  test::RunResult r =
      test::run_rtsim("run " + dir_ + "/pica.rays --resolution 64x36 -o " + dir_ + "/refused");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--resolution cannot change it"), std::string::npos) << r.err;
  r = test::run_rtsim("run " + dir_ + "/pica.rays --from-trace " + dir_ + "/pica.rays -o " + dir_ +
                      "/refused");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("give one trace"), std::string::npos) << r.err;
  test::TempDir tmp;
  std::string bad = tmp.write("bad.rays", "not a stream");
  r = test::run_rtsim("run " + bad + " -o " + tmp.path("out"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(bad), std::string::npos) << r.err;
}

TEST_F(StreamRuns, ReportOfASimFolderIsTheRunsReport) {
  std::string sim = dir_ + "/sim";
  test::RunResult r = test::run_rtsim("report " + sim + " --no-charts");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Json from_sim = test::read_json(sim + "/report.json");
  Json from_run = test::read_json(dir_ + "/run/report.json");
  for (const char* section : {"workload", "bandwidth", "dram", "coherence", "verification",
                              "latency", "hit_rates", "energy", "pixel_buffers"})
    EXPECT_EQ(from_sim[section], from_run[section]) << section;
  EXPECT_EQ(from_sim["timing"]["cycles"], from_run["timing"]["cycles"]);
  EXPECT_EQ(from_sim["hardware"]["resolved"], from_run["hardware"]["resolved"]);
  EXPECT_EQ(from_sim["command"].get<std::string>().rfind("rtsim sim ", 0), 0u)
      << from_sim["command"];
  EXPECT_TRUE(fs::exists(sim + "/report.html"));
  EXPECT_TRUE(fs::exists(sim + "/report.md"));
}

TEST_F(StreamRuns, ASimFolderWithoutItsRunRecordIsNamed) {
  test::TempDir tmp;
  std::string copy = tmp.path("sim");
  fs::copy(dir_ + "/sim", copy);
  fs::remove(copy + "/sim.json");
  fs::remove(copy + "/report.json");
  test::RunResult r = test::run_rtsim("report " + copy);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(copy + "/sim.json: missing"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(copy + "/report.html"));
}

TEST_F(StreamRuns, AnotherSimRemovesTheEarlierReport) {
  std::string sim = dir_ + "/sim-again";
  ASSERT_EQ(test::run_rtsim("sim " + dir_ + "/pica.rays -q -o " + sim).exit_code, 0);
  ASSERT_EQ(test::run_rtsim("report " + sim + " --no-charts").exit_code, 0);
  ASSERT_TRUE(fs::exists(sim + "/report.json"));
  ASSERT_EQ(test::run_rtsim("sim " + dir_ + "/pica.rays -q --set rt.count=1 -o " + sim).exit_code,
            0);
  EXPECT_FALSE(fs::exists(sim + "/report.json")) << "it described the earlier results";
  ASSERT_EQ(test::run_rtsim("report " + sim + " --no-charts").exit_code, 0);
  EXPECT_EQ(test::read_json(sim + "/report.json")["hardware"]["rt_units"], 1);
}

TEST_F(StreamRuns, AChartThatFailsIsExitOneWithTheReason) {
  std::string run = dir_ + "/charts";
  fs::copy(dir_ + "/run", run, fs::copy_options::recursive);
  test::RunResult r =
      test::run_program("RTSIM_PYTHON=/nonexistent/python3 " RTSIM_EXE, "report " + run);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.err.find("rtsim: charts failed: /nonexistent/python3 not found"), std::string::npos)
      << r.err;
  EXPECT_TRUE(fs::exists(run + "/report.html")) << "the pages say why each chart is missing";
  r = test::run_rtsim("report " + run + " --no-charts");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("charts     skipped (--no-charts)"), std::string::npos) << r.out;
  r = test::run_rtsim("report " + run);
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

}  // namespace
}  // namespace rtsim
