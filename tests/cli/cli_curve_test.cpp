// rtsim curve on a small Cornell-box frame: the files it writes, and bad input as one line, exit 2.
#include <gtest/gtest.h>

#include <filesystem>

#include "run_rtsim.h"
#include "stream_test_util.h"

namespace rtsim::test {
namespace {

TEST(CliCurve, WritesTheCurveAndRefusesBadSizes) {
  std::string stream = temp_path("curve.rays"), out = temp_path("curve-out");
  std::string spec = std::string(RTSIM_SOURCE_DIR) + "/workloads/specs/cornell.toml";
  ASSERT_EQ(run_rtsim("trace " + spec + " -o " + stream + " --resolution 64x36").exit_code, 0);
  RunResult r = run_rtsim("curve " + stream + " --l2 4K..16K --no-charts -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("curve: one pass over"), std::string::npos) << r.err;
  std::string csv = slurp(out + "/curve.csv");
  EXPECT_EQ(count_lines(csv), 4) << csv;  // header and 4K, 8K, 16K
  EXPECT_NE(csv.find("\n4096,16,"), std::string::npos) << csv;
  EXPECT_NE(slurp(out + "/curve.json").find("\"schema\": \"rtsim.curve/1\""), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(out + "/config.toml"));

  r = run_rtsim("curve " + stream + " --l2 12Q");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("--l2: '12Q' is not a size"), std::string::npos) << r.err;
  r = run_rtsim("curve " + stream + " --l2 4K --set rt.mode=treelet");  // not what the pass runs
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("curve: the default config: rt.mode"), std::string::npos) << r.err;
  r = run_rtsim("curve " + stream + " --l2 4K --simulate 3K");  // a point added, run in full
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("3 KiB"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("simulated"), std::string::npos) << r.out;
  std::filesystem::remove_all(out);
  std::filesystem::remove(stream);
}

}  // namespace
}  // namespace rtsim::test
