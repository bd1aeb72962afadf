// Units one way on the command line: `--config NAME` reads the preset configs/NAME.toml, a
// size in `--set` takes a suffix (4M) and a bad one names the --set, summaries say "hit rate",
// and a chart that fails makes curve exit 1 with the reason.
#include <gtest/gtest.h>

#include <filesystem>

#include "run_rtsim.h"
#include "stream_test_util.h"

namespace rtsim::test {
namespace {

// A small Cornell-box frame, traced once for the tests of this file.
const std::string& stream() {
  static const std::string path = [] {
    std::string p = temp_path("units.rays");
    RunResult r = run_rtsim("trace " + std::string(RTSIM_SOURCE_DIR) +
                            "/workloads/specs/cornell.toml -q -o " + p + " --resolution 32x18");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return p;
  }();
  return path;
}

TEST(CliUnits, APresetByNameAndASizeWithASuffix) {
  std::string out = temp_path("units-sim");
  RunResult r =
      run_rtsim("sim " + stream() + " -o " + out + " --set l2.size_bytes=4M --config desktop");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // desktop's L2 is 4M already: another size shows that the --set took.
  r = run_rtsim("sim " + stream() + " -o " + out + " --set l2.size_bytes=2M --config desktop");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::string config = slurp(out + "/config.toml");
  EXPECT_NE(config.find("name = \"desktop\""), std::string::npos) << config;
  size_t l2 = config.find("[memory.l2]\n");
  ASSERT_NE(l2, std::string::npos) << config;
  EXPECT_NE(config.find("\nsize_bytes = 2097152  #", l2), std::string::npos) << config;
  EXPECT_NE(r.out.find("L1 hit rate "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("L2 hit rate "), std::string::npos) << r.out;
  std::filesystem::remove_all(out);
}

TEST(CliUnits, AnUnknownPresetListsThePresets) {
  RunResult r = run_rtsim("sim " + stream() + " -o " + temp_path("units-x") + " --config nosuch");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("nosuch: no such file, nor a preset"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(presets: arc-a770, desktop, "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("mobile"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(temp_path("units-x"))) << "refused before any output";
}

TEST(CliUnits, ABadSizeInSetNamesTheSet) {
  for (const char* command : {"sim", "curve"}) {
    RunResult r = run_rtsim(std::string(command) + " " + stream() + " -o " + temp_path("units-y") +
                            " --config mobile --set l2.size_bytes=4x");
    EXPECT_EQ(r.exit_code, 2) << command << ": " << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("--set l2.size_bytes=4x: key 'l2.size_bytes': '4x': unknown suffix 'x'"),
              std::string::npos)
        << command << ": " << r.err;
  }
}

TEST(CliUnits, ACurveWhoseChartFailsIsExitOne) {
  std::string out = temp_path("units-curve");
  RunResult r = run_program("RTSIM_PYTHON=/nonexistent/python3 " RTSIM_EXE,
                            "curve " + stream() + " --l2 4K..16K -o " + out);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("rtsim: charts failed: /nonexistent/python3 not found"), std::string::npos)
      << r.err;
  EXPECT_TRUE(std::filesystem::exists(out + "/curve.md")) << "the rest is written";
  EXPECT_FALSE(std::filesystem::exists(out + "/curve.png"));
  r = run_program("RTSIM_PYTHON=/nonexistent/python3 " RTSIM_EXE,
                  "curve " + stream() + " --l2 4K..16K --no-charts -o " + out);
  EXPECT_EQ(r.exit_code, 0) << "no chart asked for: " << r.err;
  std::filesystem::remove_all(out);
}

}  // namespace
}  // namespace rtsim::test
