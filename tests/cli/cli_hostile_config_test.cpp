// Hostile configs and options (issue 63): every one ends with one line on stderr naming the file
// or the option, and exit 2, never a crash, a hang or runaway memory; a stall_cycles below the
// DRAM's latency is no stall. Inputs are generated here, in a scratch folder.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "run_rtsim.h"
#include "tests/temp_dir.h"

namespace rtsim::test {
namespace {

const std::string kMobile = std::string(RTSIM_SOURCE_DIR) + "/configs/mobile.toml";

// A small Cornell-box stream, traced once per test process.
const std::string& stream() {
  static const std::string path = [] {
    std::string out = scratch_path("hostile.rays");
    std::string spec = std::string(RTSIM_SOURCE_DIR) + "/workloads/specs/cornell.toml";
    RunResult r = run_rtsim("trace " + spec + " -o " + out + " --resolution 32x18");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return out;
  }();
  return path;
}

// Exit 2 and one line on stderr that holds every one of `parts`.
void expect_one_line_error(const RunResult& r, std::initializer_list<std::string> parts) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  for (const std::string& part : parts) EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
}

std::string dotted(int parts) {
  std::string key = "a";
  for (int i = 1; i < parts; ++i) key += ".a";
  return key;
}

TEST(CliHostileConfig, DeepTomlIsRefusedByEveryReader) {
  TempDir dir;
  std::string deep = "[" + dotted(100000) + "]\nx = 1\n";
  std::string config = dir.write("deep.toml", "[rt]\ncount = 2\n" + deep);
  expect_one_line_error(run_rtsim("scene-info cornell --bvh --config " + config),
                        {config + ": line 3: nesting depth 100000 exceeds the limit of 64"});
  std::string nested = dir.write("nested.toml", "x = " + std::string(100000, '[') + "\n");
  expect_one_line_error(run_rtsim("scene-info cornell --bvh --config " + nested),
                        {nested + ": line 1: nesting depth 65 exceeds the limit of 64"});
  std::string inline_tables = "x = {";
  for (int i = 0; i < 40; ++i) inline_tables += "a = {";
  std::string tables = dir.write("inline.toml", inline_tables + "\n");
  expect_one_line_error(run_rtsim("scene-info cornell --bvh --config " + tables),
                        {tables + ": line 1: nesting depth 65 exceeds"});

  std::string spec = dir.write("deep-spec.toml", "scene = \"cornell\"\n" + deep);
  std::string rays = dir.path("deep.rays");
  expect_one_line_error(run_rtsim("trace " + spec + " -o " + rays),
                        {spec + ": line 2: nesting depth 100000"});
  EXPECT_FALSE(std::filesystem::exists(rays));
  std::string sweep = dir.write("sweep.toml", deep);
  expect_one_line_error(run_rtsim("sweep " + sweep + " -o " + dir.path("sweep-out")),
                        {sweep + ": line 1: nesting depth 100000"});
  std::string suite = dir.write("suite.toml", deep);
  expect_one_line_error(run_rtsim("regress " + suite + " --baseline " + dir.path("base") + " -o " +
                                  dir.path("regress-out")),
                        {suite + ": line 1: nesting depth 100000"});
  std::string set = dotted(1000) + "=1";
  expect_one_line_error(run_rtsim("scene-info cornell --bvh --set " + set),
                        {"--set a.a.a", "nesting depth 1000 exceeds"});
  int entries = 0;  // the inputs alone: no output, no temporary
  for (const auto& entry : std::filesystem::directory_iterator(dir.path(""))) {
    EXPECT_EQ(entry.path().extension(), ".toml") << entry.path();
    ++entries;
  }
  EXPECT_EQ(entries, 6);
}

TEST(CliHostileConfig, CurveChecksSizesAndPlansMemory) {
  RunResult r = run_rtsim("curve " + stream() + " --config " + kMobile + " --l2 1G..1000G");
  expect_one_line_error(
      r, {"curve: --l2: '1000G' is out of range [64, 16G] (the limits of memory.l2.size_bytes)"});
  r = run_rtsim("curve " + stream() + " --l2 4K --l1 99999999999G");
  expect_one_line_error(r, {"curve: --l1: '99999999999G' is more than 2^64-1 bytes"});
  r = run_rtsim("curve " + stream() + " --l2 4x");
  expect_one_line_error(r, {"curve: --l2: '4x': unknown suffix 'x'"});
  r = run_rtsim("curve " + stream() + " --l2 4K --simulate 32");
  expect_one_line_error(r, {"curve: --simulate: '32' is out of range"});

  setenv("RTSIM_MAX_MEMORY", "100000000", 1);  // 100 MB: 1 GB of L2 is 16M lines
  r = run_rtsim("curve " + stream() + " --config " + kMobile + " --l2 256M..1G");
  unsetenv("RTSIM_MAX_MEMORY");
  expect_one_line_error(
      r, {"curve: --l2 256M..1G: the curve's cache model needs about", "GB of memory"});
  EXPECT_EQ(r.err.find("pass over"), std::string::npos) << "refused before the pass: " << r.err;

  // A size that is no whole number of sets at an associativity is rounded down, and said so.
  r = run_rtsim("curve " + stream() + " --config " + kMobile + " --l2 4K --ways 3");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("curve: 4096 bytes is 3840 bytes in whole sets of memory.l2's 2 slices"),
            std::string::npos)
      << r.err;
  r = run_rtsim("curve " + stream() + " --l2 4K --set rt.mode=treelet");
  expect_one_line_error(r, {"curve: --set rt.mode=treelet: rt.mode"});
}

TEST(CliHostileConfig, BandwidthsHaveAFloor) {
  for (const char* key : {"l2", "rt.l1", "xbar"}) {
    std::string set = std::string(key) + ".bytes_per_cycle=1e-30";
    RunResult r = run_rtsim("sim " + stream() + " --set " + set + " -o " + scratch_path("bw"));
    expect_one_line_error(r, {"--set " + set + ": key '" + key +
                              ".bytes_per_cycle': 1e-30 is out "
                              "of range [1, 1000000] (or 0: no limit)"});
    EXPECT_FALSE(std::filesystem::exists(scratch_path("bw")));
  }
  RunResult keys = run_rtsim("sim --list-keys");
  EXPECT_NE(
      keys.out.find("data port bandwidth (reads and writes); 0 = no limit, else 1 to 1000000"),
      std::string::npos)
      << keys.out;
}

TEST(CliHostileConfig, StallCyclesBelowTheDramLatencyIsNoStall) {
  std::string out = scratch_path("stall");
  RunResult r = run_rtsim("sim " + stream() + " --config " + kMobile +
                          " --set sim.stall_cycles=100 --no-verify -q -o " + out);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::filesystem::remove_all(out);
}

TEST(CliHostileConfig, AnImpossibleCombinationNamesTheOverride) {
  RunResult r = run_rtsim("scene-info cornell --bvh --config " + kMobile + " --set l2.ways=3");
  expect_one_line_error(r, {"rtsim: error: --set l2.ways=3: [l2] size_bytes must be"});
  r = run_rtsim("scene-info cornell --bvh --config " + kMobile + " --set rt.count=many");
  expect_one_line_error(r, {"--set rt.count=many: key 'rt.count': expected an integer"});
}

}  // namespace
}  // namespace rtsim::test
