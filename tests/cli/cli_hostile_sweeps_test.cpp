// Hostile sweep specs, regression suites and documents read back (issue 63): each ends with
// exit 2 and one line on stderr naming the file and the place (line or JSON key), before
// anything is written.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/cli/run_rtsim.h"
#include "tests/temp_dir.h"

namespace rtsim {
namespace {

namespace fs = std::filesystem;
using test::run_rtsim;

// Expects exit 2 and one line on stderr holding each of `wanted`.
void expect_refused(const test::RunResult& r, std::initializer_list<std::string> wanted) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  for (const std::string& w : wanted) EXPECT_NE(r.err.find(w), std::string::npos) << r.err;
}

// The names of the entries of dir (none if it does not exist).
size_t entries(const std::string& dir) {
  if (!fs::exists(dir)) return 0;
  return size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

const std::string kPica = "[[workload]]\nworkload = \"pica\"\nresolution = \"16x9\"\n";

TEST(HostileSweeps, AGridOf2To64PointsIsRefusedFromItsCheckedCount) {
  test::TempDir dir;
  std::string grid = kPica + "[grid]\n";
  for (int k = 0; k < 16; ++k) {
    grid += "k" + std::to_string(k) + " = [";
    for (int v = 0; v < 16; ++v) grid += std::to_string(v) + (v < 15 ? ", " : "]\n");
  }
  std::string spec = dir.write("huge.toml", grid);
  expect_refused(run_rtsim("sweep " + spec + " -o " + dir.path("out")),
                 {spec + ": line 4: the grid has at least 18446744073709551615 points (16 x 16",
                  "narrow it (--max-points takes at most 1000000)"});
  EXPECT_FALSE(fs::exists(dir.path("out")));
  // Workloads multiply the points of a list too.
  std::string list = dir.write("list.toml",
                               "[[workload]]\nname = \"a\"\n[[workload]]\n"
                               "name = \"b\"\n[[workload]]\nname = \"c\"\n"
                               "[[point]]\n\"rt.count\" = 1\n[[point]]\n"
                               "\"rt.count\" = 2\n");
  expect_refused(run_rtsim("sweep " + list + " -o " + dir.path("out") + " --max-points 5"),
                 {list + ": line 7: the [[point]] list has 6 points (2 [[point]] x 3 workloads)"});
  expect_refused(run_rtsim("sweep " + list + " -o " + dir.path("out") + " --max-points 1000001"),
                 {"--max-points"});
  // A grid of one point but thousands of keys is refused before it is expanded.
  std::string keys = kPica + "[grid]\n";
  for (int k = 0; k < 5000; ++k) keys += "k" + std::to_string(k) + " = [1]\n";
  std::string wide = dir.write("wide.toml", keys);
  expect_refused(run_rtsim("sweep " + wide + " -o " + dir.path("out")),
                 {wide + ": line 4: 5000 keys, more than 1000"});
}

TEST(HostileSweeps, ANameFromASpecNeverLeavesTheOutputFolder) {
  test::TempDir dir;
  fs::create_directories(dir.path("victim"));
  std::string victim = dir.write("victim/trace.json", "the user's own file\n");
  for (std::string name : {"../../victim", "..", "", ".hidden", "a/b", "/tmp/x", "a\\\\b"}) {
    std::string spec = dir.write("s.toml", "[[workload]]\nworkload = \"pica\"\nname = \"" + name +
                                               "\"\n[grid]\n\"rt.count\" = [1]\n");
    expect_refused(run_rtsim("sweep " + spec + " -o " + dir.path("out")),
                   {spec + ": line 3: [[workload]] name", "one path component"});
    std::string suite = dir.write("suite.toml", "[[case]]\nworkload = \"pica\"\nname = \"" + name +
                                                    "\"\n[tolerance]\ncycles = 0\n");
    expect_refused(run_rtsim("regress " + suite + " --baseline " + dir.path("base") + " -o " +
                             dir.path("out")),
                   {suite + ": line 3: [[case]] name"});
  }
  // A Slurm task clears its points' folders: an id from its tasks file never leads outside.
  std::string tasks =
      dir.write("tasks.json", R"({"schema": "rtsim.sweep.slurm-tasks/1",
      "sweep": ")" + dir.path("sweep") +
                                  R"(", "tasks": [[{"id": "../../victim", "workload": "w"}]]})");
  expect_refused(run_rtsim("sweep --slurm-task " + tasks + " --task 0"),
                 {tasks + ": key tasks.0.0.id: '../../victim' starts with '.'"});
  EXPECT_EQ(test::slurp(victim), "the user's own file\n");
  EXPECT_EQ(entries(dir.path("")), 4u) << "no output folder, no temporary: the specs and victim/";
  EXPECT_EQ(entries(dir.path("victim")), 1u);
  // A workload's default name is its file's stem: a hidden spec file needs a name.
  std::string hidden = dir.write(".w.toml", "");
  std::string spec =
      dir.write("s.toml", "[[workload]]\nworkload = \"" + hidden + "\"\n[grid]\nk = [1]\n");
  expect_refused(run_rtsim("sweep " + spec + " -o " + dir.path("out")),
                 {spec + ": line 1: [[workload]] name: '.w' starts with '.'"});
}

TEST(HostileSweeps, PointsThatWouldShareAFolderAreRefusedNamingTheirLines) {
  test::TempDir dir;
  std::string grid = dir.write("grid.toml", kPica + "[grid]\n\"rt.count\" = [2, 2]\n");
  expect_refused(run_rtsim("sweep " + grid + " -j 2 -o " + dir.path("out")),
                 {grid + ": line 5: grid key 'rt.count' lists 2 twice"});
  std::string list = dir.write("list.toml", kPica +
                                                "[[point]]\n\"rt.count\" = 2\nl2.size_bytes = 65536"
                                                "\n[[point]]\nl2 = { size_bytes = 65536 }\n"
                                                "\"rt.count\" = 2\n");
  expect_refused(run_rtsim("sweep " + list + " -o " + dir.path("out")),
                 {list + ": line 7: this [[point]] sets the same values as the one on line 4"});
  std::string twice =
      dir.write("twice.toml", kPica + "[grid]\n\"rt.count\" = [1]\n[grid.rt]\ncount = [2]\n");
  expect_refused(run_rtsim("sweep " + twice + " -o " + dir.path("out")),
                 {twice + ": line 7: 'rt.count' is given twice, on lines 5 and 7"});
  EXPECT_FALSE(fs::exists(dir.path("out")));
}

TEST(HostileSweeps, AMalformedDocumentReadBackNamesItsFileAndKey) {
  test::TempDir dir;
  fs::create_directories(dir.path("run"));
  std::string report = dir.write(
      "run/report.json", R"({"schema": "rtsim.report/1", "generator": "rtsim", "command": "run"})");
  expect_refused(run_rtsim("report --no-charts " + dir.path("run")),
                 {report + ": key workload: missing (expected an object)"});
  fs::create_directories(dir.path("sweep"));
  std::string point = R"({"id": "a", "workload": "w", "status": "done", "ran_on": "",
                          "values": {}, "metrics": 5})";
  std::string doc = R"({"schema": "rtsim.sweep/1", "generator": "rtsim",
      "spec": {"name": "s", "file": "s.toml", "description": "", "config": "",
               "fidelity": "cycle", "workloads": [], "keys": []},
      "points": [)" +
                    point + R"(], "charts": [], "objective": null})";
  std::string sweep = dir.write("sweep/sweep.json", doc);
  expect_refused(run_rtsim("report --no-charts " + dir.path("sweep")),
                 {sweep + ": key points.0.metrics: expected an object or null, found number"});
  EXPECT_FALSE(fs::exists(dir.path("sweep/sweep.html")));
  // A chart's id names its image: it never leads outside the folder.
  std::string chart = R"({"id": "a/../../x", "kind": "curve", "x": "k", "y": "cycles",
      "series": "workload", "title": "t", "reason": "", "file": "../../x.png"})";
  doc = R"({"schema": "rtsim.sweep/1", "generator": "rtsim",
      "spec": {"name": "s", "file": "s.toml", "description": "", "config": "",
               "fidelity": "cycle", "workloads": [], "keys": []},
      "points": [], "charts": [)" +
        chart + R"(], "objective": null})";
  sweep = dir.write("sweep/sweep.json", doc);
  expect_refused(run_rtsim("report --no-charts " + dir.path("sweep")),
                 {sweep + ": key charts.0.id: 'a/../../x' holds a '/'"});
}

TEST(HostileSweeps, AnUnknownChartMetricOrConflictingOptionsAreRefused) {
  test::TempDir dir;
  std::string spec = dir.write(
      "s.toml",
      kPica + "[grid]\n\"rt.count\" = [1, 2]\n[[chart]]\nx = \"rt.count\"\ny = \"cycels\"\n");
  expect_refused(run_rtsim("sweep " + spec + " -o " + dir.path("out")),
                 {spec + ": line 8: chart y: unknown metric 'cycels'"});
  spec = dir.write("s.toml", kPica +
                                 "[grid]\n\"rt.count\" = [1, 2]\n[[chart]]\nx = \"rt.count\"\n"
                                 "series = \"rt.cuont\"\n");
  expect_refused(run_rtsim("sweep " + spec + " -o " + dir.path("out")),
                 {spec + ": line 8: chart series 'rt.cuont'"});
  std::string config = std::string(RTSIM_SOURCE_DIR) + "/configs/mobile.toml";
  expect_refused(run_rtsim("multi-device pica -o " + dir.path("out") + " --config " + config +
                           " --device-config " + config),
                 {"multi-device: give one config for every device"});
  expect_refused(run_rtsim("sweep --status " + dir.path("out") + " --max-points 5"),
                 {"--max-points goes with a SPEC"});
  expect_refused(run_rtsim("sweep " + spec + " -o " + dir.path("out") + " --trace-only -j 2"),
                 {"sweep: --jobs does nothing with --trace-only"});
  expect_refused(run_rtsim("regress " + spec + " --baseline " + dir.path("b") +
                           " --update-baseline --junit " + dir.path("j.xml")),
                 {"--junit goes with a comparison"});
  EXPECT_FALSE(fs::exists(dir.path("out")));
}

}  // namespace
}  // namespace rtsim
