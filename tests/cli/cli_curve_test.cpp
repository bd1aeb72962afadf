// rtsim curve on a small Cornell-box frame: the files it writes (one curve, or one per L1 size),
// and bad input as one line, exit 2.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

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
  EXPECT_NE(slurp(out + "/curve.json").find("\"schema\": \"rtsim.curve/2\""), std::string::npos);
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
    auto json = nlohmann::json::parse(slurp(out + "/l1-" + l1 + "/curve.json"));
    return json["pass"]["reads"].get<uint64_t>();
  };
  EXPECT_GT(l2_reads("1K"), l2_reads("16K"));
  EXPECT_GT(l2_reads("16K"), 0u);
  std::filesystem::remove_all(out);
  std::filesystem::remove(stream);
}

// Any level of a listed hierarchy: the victim-filled last level of the four-level example (its l2
// cut to 32 KB, so that a pica frame's BVH overflows it and its evictions fill the ic) at
// capacities its 6 slices do not divide (rounded down to whole sets, and said so), and a group
// level; bad --level and --l2 uses are one line, exit 2.
TEST(CliCurve, CurvesAnyLevelOfFourLevels) {
  std::string stream = temp_path("curve4.rays"), out = temp_path("curve4-out");
  std::string spec = std::string(RTSIM_SOURCE_DIR) + "/workloads/specs/pica.toml";
  std::string config = std::string(RTSIM_SOURCE_DIR) +
                       "/configs/examples/four-levels.toml --set memory.l2.size_bytes=32768";
  ASSERT_EQ(run_rtsim("trace " + spec + " -o " + stream + " --resolution 64x36").exit_code, 0);
  RunResult r = run_rtsim("curve " + stream + " --config " + config +
                          " --level ic --size 16M..128M --no-charts -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("curve: 16777216 bytes is 16773120 bytes in whole sets of memory.ic's 6 "
                       "slices"),
            std::string::npos)
      << r.err;
  auto doc = nlohmann::json::parse(slurp(out + "/curve.json"));
  EXPECT_EQ(doc["context"]["level"], "ic");
  EXPECT_EQ(doc["context"]["fill"], "victim");
  EXPECT_EQ(doc["context"]["above_dram"], true);
  ASSERT_EQ(doc["points"].size(), 4u);
  EXPECT_EQ(doc["points"][0]["capacity_bytes"].get<uint64_t>(), 16773120u);
  EXPECT_GT(doc["pass"]["fills"].get<uint64_t>(), 0u) << "the l2's evictions reach the ic";
  EXPECT_GT(doc["pass"]["reads"].get<uint64_t>(), 0u);
  for (size_t i = 1; i < 4; ++i)
    EXPECT_LE(doc["points"][i]["misses"].get<double>(),
              doc["points"][i - 1]["misses"].get<double>());
  EXPECT_NE(r.out.find("ic "), std::string::npos) << r.out;

  r = run_rtsim("curve " + stream + " --config " + config + " --level l1 --size 64K..256K");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("LRU stacks per set"), std::string::npos) << r.err;

  for (const char* bad : {" --level l9", " --level l1 --l2 1M", " --l2 1M --size 1M",
                          " --level l0 --l1 16K --size 64K"}) {
    r = run_rtsim("curve " + stream + " --config " + config + bad);
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_EQ(count_lines(r.err), 1) << bad << ": " << r.err;
  }
  r = run_rtsim("curve " + stream + " --config " + config + " --level l9");
  EXPECT_NE(r.err.find("--level l9: no such cache level (this machine has l0, l1, l2, ic)"),
            std::string::npos)
      << r.err;
  std::filesystem::remove_all(out);
  std::filesystem::remove(stream);
}

}  // namespace
}  // namespace rtsim::test
