// rtsim curve on a small Cornell-box frame: the files it writes (one curve, or one per L1 size),
// and bad input as one line, exit 2.
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
  EXPECT_NE(r.err.find("curve: pass over"), std::string::npos) << r.err;
  std::string csv = slurp(out + "/curve.csv");
  EXPECT_EQ(count_lines(csv), 4) << csv;  // header and 4K, 8K, 16K
  EXPECT_NE(csv.find("\n4096,16,"), std::string::npos) << csv;
  EXPECT_NE(slurp(out + "/curve.json").find("\"schema\": \"rtsim.curve/1\""), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(out + "/config.toml"));

  r = run_rtsim("curve " + stream + " --l2 12Q");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("--l2: '12Q': unknown suffix 'Q'"), std::string::npos) << r.err;
  r = run_rtsim("curve " + stream + " --l2 4K --set rt.mode=treelet");  // not what the pass runs
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("curve: --set rt.mode=treelet: rt.mode"), std::string::npos) << r.err;
  r = run_rtsim("curve " + stream + " --l2 4K --simulate 3K");  // a point added, run in full
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("3 KiB"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("simulated"), std::string::npos) << r.out;
  r = run_rtsim("curve " + stream + " --l2 4K --l1 1000");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("curve: --l1: 1000 bytes: size_bytes must be"), std::string::npos) << r.err;

  // One curve per L1 size: a larger L1 sends fewer reads to the L2.
  std::filesystem::remove_all(out);
  r = run_rtsim("curve " + stream + " --l2 4K..8K --l1 1K,16K --no-charts -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::string family = slurp(out + "/curve-l1.md");
  EXPECT_NE(family.find("| 1 KiB | 4 KiB |"), std::string::npos) << family;
  EXPECT_NE(family.find("| 16 KiB | 8 KiB |"), std::string::npos) << family;
  auto l2_reads = [&](const std::string& l1) {
    std::string json = slurp(out + "/l1-" + l1 + "/curve.json");
    size_t at = json.find("\"l2_reads\": ");
    return at == std::string::npos ? 0 : std::stoull(json.substr(at + 12));
  };
  EXPECT_GT(l2_reads("1K"), l2_reads("16K"));
  EXPECT_GT(l2_reads("16K"), 0u);
  std::filesystem::remove_all(out);
  std::filesystem::remove(stream);
}

}  // namespace
}  // namespace rtsim::test
