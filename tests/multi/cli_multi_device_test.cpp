// rtsim multi-device end to end: a small pica workload (30 frames, irregular samples, orbiting
// camera) traced and rendered by 4 mobile-like devices with all three strategies; and bad input
// ending with one line and exit code 2.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "run_rtsim.h"

namespace rtsim {
namespace {

const std::string kSource = RTSIM_SOURCE_DIR;

std::string out_dir(const std::string& name) {
  return "/tmp/rtsim-multi-cli-" + std::to_string(getpid()) + "-" + name;
}

TEST(CliMultiDevice, ThirtyFramesOfPicaOnFourDevices) {
  std::string dir = out_dir("pica");
  test::RunResult r =
      test::run_rtsim("multi-device " + kSource +
                      "/tests/multi/pica-tiny.toml "
                      "--devices-file " +
                      kSource + "/configs/multi/four-mobile.toml -j 2 --no-charts -o " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  std::printf("%s", r.out.c_str());  // the deviation figures, in the test log
  EXPECT_NE(r.out.find("avg max dev"), std::string::npos) << r.out;
  for (const char* name : {"static", "balanced", "cost", "current"})
    EXPECT_NE(r.out.find(std::string("\n") + name + " "), std::string::npos) << name;
  for (const char* file :
       {"report.json", "report.md", "frames.csv", "devices.csv", "workload.rays"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + file)) << file;
  auto report = nlohmann::json::parse(test::slurp(dir + "/report.json"));
  EXPECT_EQ(report["schema"], "rtsim.multi.report/1");
  EXPECT_EQ(report["input"]["frames"], 30);
  ASSERT_EQ(report["runs"].size(), 4u);
  for (const auto& run : report["runs"]) {
    ASSERT_EQ(run["frames"].size(), 30u);
    for (const auto& frame : run["frames"]) {
      EXPECT_GT(frame["speedup"].get<double>(), 1.0);
      EXPECT_GT(frame["copy_bytes"].get<double>(), 0.0);
      ASSERT_EQ(frame["devices"].size(), 4u);
    }
  }
  const auto& summary = report["summary"];
  double fixed = summary[0]["avg_max_deviation_pct"];
  double balanced = summary[1]["avg_max_deviation_pct"];
  double cost = summary[2]["avg_max_deviation_pct"];
  EXPECT_LT(balanced, fixed) << "balanced beats static";
  EXPECT_LT(cost, fixed) << "cost-weighted beats static";
  std::string md = test::slurp(dir + "/report.md");
  EXPECT_NE(md.find("| static |"), std::string::npos);
  EXPECT_NE(md.find("| balanced |"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(CliMultiDevice, ChartFromTheCsvFiles) {
  std::string dir = out_dir("chart");
  test::RunResult trace = test::run_rtsim("trace " + kSource +
                                          "/tests/multi/pica-tiny.toml "
                                          "--frames 3 --resolution 32x18 -q -o " +
                                          dir + ".rays");
  ASSERT_EQ(trace.exit_code, 0) << trace.err;
  test::RunResult r = test::run_rtsim("multi-device " + dir + ".rays --config " + kSource +
                                      "/configs/mobile.toml --devices 2 -j 2 -q -o " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir + "/chart.png")) << r.err;
  EXPECT_NE(test::slurp(dir + "/report.md").find("chart.png"), std::string::npos);

  // A chart that cannot be drawn: the report all the same, the reason, exit 1.
  std::filesystem::remove_all(dir);
  r = test::run_program(
      "RTSIM_PYTHON=/nonexistent/python3 " RTSIM_EXE,
      "multi-device " + dir + ".rays --config mobile --devices 2 -j 2 -q -o " + dir);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.err.find("rtsim: charts failed: /nonexistent/python3 not found"), std::string::npos)
      << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir + "/report.md"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/chart.png"));
  std::filesystem::remove_all(dir);
  std::filesystem::remove(dir + ".rays");
}

TEST(CliMultiDevice, BadInputIsOneLineAndExitTwo) {
  std::string set = kSource + "/configs/multi/four-mobile.toml";
  std::string missing = "multi-device /nonexistent.rays --devices-file " + set + " -o /tmp/x";
  std::string bad_split = "multi-device x.rays --devices-file " + set + " --split static,afr -o x";
  std::string bad_key =
      "multi-device x.rays --devices-file " + set + " --device-set link.nope=1 -o x";
  std::string both = "multi-device x.rays --devices-file " + set + " --config a.toml -o x";
  std::string no_set = "multi-device x.rays --devices-file /nonexistent.toml -o x";
  std::string bad_unit =
      "multi-device x.rays --devices-file " + set + " --device-set split.samples=px -o x";
  std::string warmup = "multi-device x.rays --devices-file " + set + " --warmup-frames 3 -o x";
  for (const std::string& args : {missing, bad_split, bad_key, both, no_set, bad_unit, warmup}) {
    test::RunResult r = test::run_rtsim(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_EQ(test::count_lines(r.err), 1) << args << "\n" << r.err;
  }
}

// --set means hardware keys as in every other command; device-set keys have their own option.
TEST(CliMultiDevice, SetIsForHardwareKeysAndDeviceSetForTheSetsKeys) {
  std::string set = kSource + "/configs/multi/four-mobile.toml";
  test::RunResult r = test::run_rtsim("multi-device x.rays --devices-file " + set +
                                      " --set link.bandwidth_gbps=32 -o x");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(
      test::first_line(r.err),
      "rtsim: error: --set link.bandwidth_gbps=32: a device-set key, not a hardware key: pass "
      "it as --device-set link.bandwidth_gbps=32")
      << r.err;
  r = test::run_rtsim("multi-device x.rays --devices-file " + set + " --set rt.nope=1 -o x");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(test::first_line(r.err).find("--set rt.nope=1: unknown key 'rt.nope'"),
            std::string::npos)
      << r.err;
  r = test::run_rtsim("multi-device x.rays --devices-file " + set +
                      " --device-set link.bandwidth_gbps=-1 -o x");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(test::first_line(r.err).find("--device-set link.bandwidth_gbps"), std::string::npos)
      << r.err;
}

TEST(CliMultiDevice, ListKeys) {
  test::RunResult r = test::run_rtsim("multi-device --list-keys");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* key : {"link.bandwidth_gbps", "flow.raygen_ns_per_pixel", "split.strategies",
                          "device[].config", "change[].frame"})
    EXPECT_NE(r.out.find(key), std::string::npos) << key;
}

}  // namespace
}  // namespace rtsim
