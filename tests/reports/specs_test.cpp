// Sweep specs and regression suites: grids multiply, lists list, relative paths resolve next to
// the file, and every mistake is an InputError naming the file and line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "reports/regress_suite.h"
#include "reports/sweep_spec.h"
#include "tests/reports/report_test_util.h"
#include "traces/error.h"

namespace rtsim::reports {
namespace {

std::string write(const std::string& name, const std::string& text) {
  std::string dir = test::fresh_dir("specs");
  std::filesystem::copy_file(test::source_path("configs/mobile.toml"), dir + "/hw.toml");
  std::ofstream(dir + "/" + name) << text;
  return dir + "/" + name;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SweepSpec, AGridIsTheProductOfItsLists) {
  SweepSpec s = read_sweep_spec(write("s.toml", R"(config = "hw.toml"
[[workload]]
workload = "pica"
[[workload]]
workload = "cornell"
[grid]
"rt.l1.size_bytes" = [8192, 16384, 32768]
l2.size_bytes = [65536, 131072]
"rt.mode" = ["depth_first", "treelet"]
)"));
  EXPECT_EQ(s.points.size(), 12u);
  EXPECT_EQ(s.workloads.size(), 2u);
  EXPECT_EQ(s.keys.size(), 3u) << "nested tables flatten to dotted keys";
  EXPECT_NE(s.config.find("hw.toml"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(s.config)) << "resolved next to the spec";
  bool quoted = false;
  for (const std::string& set : s.points[0].sets) quoted |= set == "rt.mode=\"depth_first\"";
  EXPECT_TRUE(quoted) << "strings are passed in TOML syntax";
}

TEST(SweepSpec, SizesTakeSuffixesAndAConfigMayBeAPreset) {
  SweepSpec s = read_sweep_spec(write("s.toml", R"(config = "mobile"
[[workload]]
workload = "cornell"
[grid]
"l2.size_bytes" = ["256K", "1M", 2097152]
"rt.mode" = ["treelet"]
)"));
  EXPECT_EQ(s.config, "mobile") << "no file of that name: the preset, read by load_hw_config";
  ASSERT_EQ(s.points.size(), 3u);
  EXPECT_EQ(s.points[0].values["l2.size_bytes"], 262144) << "a size is its bytes";
  EXPECT_EQ(s.points[1].values["l2.size_bytes"], 1048576);
  EXPECT_EQ(s.points[0].sets[0], "l2.size_bytes=262144");
  EXPECT_EQ(s.points[0].sets[1], "rt.mode=\"treelet\"") << "other strings stay strings";
  std::string e = error_of([&] {
    read_sweep_spec(write("s.toml",
                          "[[workload]]\nworkload = \"cornell\"\n[grid]\n"
                          "\"l2.size_bytes\" = [\"1M\", \"1MiB\"]\n"));
  });
  EXPECT_NE(e.find("lists 1048576 twice"), std::string::npos) << "1M is 1MiB: " << e;
  e = error_of([&] {
    read_sweep_spec(write(
        "s.toml", "[[workload]]\nworkload = \"cornell\"\n[grid]\n\"l2.size_bytes\" = [\"4x\"]\n"));
  });
  EXPECT_NE(e.find("line 4: l2.size_bytes=\"4x\": key 'l2.size_bytes': '4x': unknown suffix 'x'"),
            std::string::npos)
      << e;
}

TEST(SweepSpec, AListGivesItsPoints) {
  SweepSpec s = read_sweep_spec(write("s.toml", R"([[workload]]
workload = "pica"
[[point]]
"rt.count" = 2
[[point]]
"rt.count" = 8
"l2.size_bytes" = 1048576
)"));
  ASSERT_EQ(s.points.size(), 2u);
  EXPECT_EQ(s.points[1].sets.size(), 2u);
  EXPECT_EQ(s.keys.size(), 2u);
}

TEST(SweepSpec, AGridIsCountedBeforeItIsExpandedAndRefusedAboveTheLimit) {
  std::string grid = "[[workload]]\n[grid]\n\"rt.count\" = [1, 2]\n\"rt.warps\" = [1, 2, 4]\n";
  EXPECT_EQ(read_sweep_spec(write("s.toml", grid), 6).points.size(), 6u);
  std::string error = error_of([&] { read_sweep_spec(write("s.toml", grid), 5); });
  EXPECT_NE(error.find("line 2: the grid has 6 points (2 x 3), more than the limit of 5"),
            std::string::npos)
      << error;
  EXPECT_NE(error.find("--max-points 6"), std::string::npos) << error;
  // A million points: refused from the count alone, with nothing expanded.
  std::string values = "[";
  for (int i = 1; i <= 100; ++i) values += std::to_string(i) + (i < 100 ? ", " : "]");
  std::string huge = "[[workload]]\n[grid]\n\"rt.count\" = " + values +
                     "\n\"rt.warps\" = " + values + "\n\"rt.warp_size\" = " + values + "\n";
  EXPECT_NE(error_of([&] {
              read_sweep_spec(write("s.toml", huge));
            }).find("the grid has 1000000 points (100 x 100 x 100), more than the limit of 10000"),
            std::string::npos);
}

TEST(SweepSpec, MistakesNameTheFileAndLine) {
  EXPECT_NE(error_of([] {
              read_sweep_spec(write("s.toml",
                                    "[[workload]]\nworkload = \"pica\"\n"
                                    "[grid]\n\"rt.count\" = [1]\nbogus = 1\n"));
            }).find("line 5"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              read_sweep_spec(write("s.toml", "[[workload]]\n[grid]\n\"rt.nope\" = [1]\n"));
            }).find("rt.nope"),
            std::string::npos)
      << "config keys are checked before anything runs";
  EXPECT_NE(error_of([] {
              read_sweep_spec(write("s.toml",
                                    "[[workload]]\n[grid]\n\"rt.count\" = [1]\n"
                                    "[[point]]\n\"rt.count\" = 2\n"));
            }).find("not both"),
            std::string::npos);
  EXPECT_NE(error_of([] { read_sweep_spec(write("s.toml", "[[workload]]\n")); }).find("no [grid]"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              read_sweep_spec(write("s.toml",
                                    "[[workload]]\n[[workload]]\n[grid]\n"
                                    "\"rt.count\" = [1]\n"));
            }).find("line 2: two workloads are named 'pica'"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              read_sweep_spec(write("s.toml",
                                    "[[workload]]\n[grid]\n\"rt.count\" = [1]\n"
                                    "[run]\nfidelity = \"fast\"\n"));
            }).find("line 5: 'fidelity' must be"),
            std::string::npos)
      << "checked when read, not point by point";
}

// The examples reports/README.md points users to read as they are documented.
TEST(SweepSpec, EveryExampleReads) {
  size_t sweeps = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(test::source_path("reports/examples"))) {
    std::string path = entry.path().string();
    if (test::slurp(path).find("[[case]]") != std::string::npos) {
      EXPECT_FALSE(read_regress_suite(path).cases.empty()) << path;
      continue;
    }
    EXPECT_FALSE(read_sweep_spec(path).points.empty()) << path;
    ++sweeps;
  }
  EXPECT_GE(sweeps, 6u);
  SweepSpec energy = read_sweep_spec(test::source_path("reports/examples/energy-budget.toml"));
  EXPECT_EQ(energy.objective.metric, "energy_nj_per_ray");
  EXPECT_EQ(energy.points.size(), 15u);
}

TEST(SweepSpec, AnObjectiveNamesAMetricAndItsBounds) {
  std::string grid = "[[workload]]\n[grid]\n\"rt.count\" = [1, 2]\n";
  SweepSpec spec =
      read_sweep_spec(write("s.toml", grid + "[objective]\nmaximise = \"mrays_per_joule\"\n"
                                             "at_most = { sram_area_mm2 = 10 }\n"
                                             "at_least = { mrays_per_second = 500 }\n"));
  EXPECT_EQ(spec.objective.metric, "mrays_per_joule");
  EXPECT_TRUE(spec.objective.maximise);
  ASSERT_EQ(spec.objective.at_most.size(), 1u);
  EXPECT_EQ(spec.objective.at_most[0], std::make_pair(std::string("sram_area_mm2"), 10.0));
  EXPECT_EQ(spec.objective.at_least[0].first, "mrays_per_second");
  auto fails = [&](const std::string& objective, const std::string& what) {
    std::string e = error_of([&] { read_sweep_spec(write("s.toml", grid + objective)); });
    EXPECT_NE(e.find(what), std::string::npos) << objective << " gave: " << e;
  };
  fails("[objective]\nminimise = \"joules\"\n", "line 5: unknown metric 'joules'");
  fails("[objective]\nat_most = { area_mm2 = 1 }\n", "needs one of minimise or maximise");
  fails("[objective]\nminimise = \"cycles\"\nmaximise = \"cycles\"\n", "one of minimise");
  fails("[objective]\nminimise = \"type.*.dynamic_energy_nj_per_ray\"\n", "pick one");
  fails("[objective]\nminimise = \"cycles\"\nat_most = { area_mm2 = \"big\" }\n",
        "line 6: at_most.area_mm2 must be a number");
  fails("[objective]\nminimise = \"cycles\"\nat_least = { nope = 1 }\n", "unknown metric 'nope'");
  fails("[objective]\nminimise = \"cycles\"\nbudget = 3\n", "unknown key 'budget'");
  fails("[objective]\nminimise = \"cycles\"\nat_most = { \"type.*.rays\" = 1 }\n", "pick one");
}

TEST(SweepSpec, BadWorkloadsAndSettingsBlameTheSpecsLineNotAnOptionOrThePreset) {
  auto error = [](const std::string& text) {
    std::string path = write("s.toml", text);
    std::string e = error_of([&] { read_sweep_spec(path); });
    return e.substr(std::min(e.size(), path.size() + 2));  // after "PATH: "
  };
  EXPECT_EQ(error("config = \"hw.toml\"\n[[workload]]\nresolution = \"8xx8\"\n[grid]\n"),
            "line 3: resolution '8xx8': expected WxH, e.g. \"1920x1080\"");
  EXPECT_EQ(error("[[workload]]\nworkload = \"gone.toml\"\n[grid]\n"),
            "line 2: workload 'gone.toml': no such workload spec (.toml), scene file or built-in "
            "scene");
  EXPECT_EQ(error("config = \"hw.toml\"\n[[workload]]\n[grid]\n\"l2.size_bytes\" = [65536, "
                  "65537]\n"),
            "line 4: l2.size_bytes=65537: [l2] size_bytes must be a positive multiple of "
            "line_bytes * ways");
  EXPECT_EQ(error("config = \"hw.toml\"\nset = [\"rt.count=2\", \"l2.nope=1\"]\n[[workload]]\n"
                  "[grid]\n")
                .substr(0, 40),
            "line 2: l2.nope=1: unknown key 'l2.nope'");
  EXPECT_EQ(error("config = \"hw.toml\"\n[[workload]]\n[[point]]\n\"rt.count\" = 2\n\n[[point]]\n"
                  "\"rt.count\" = 0\n")
                .substr(0, 19),
            "line 7: rt.count=0:");
}

TEST(RegressSuite, AToleranceOnAnUnknownMetricNamesItsLine) {
  auto suite = [](const std::string& tolerances) {
    return "[[case]]\nname = \"a\"\n[tolerance]\ncycles = 0.02\n" + tolerances;
  };
  std::string e = error_of([&] { read_regress_suite(write("r.toml", suite("cycels = 0.01\n"))); });
  EXPECT_NE(e.find("r.toml: line 5: [tolerance] unknown metric 'cycels' (metrics: cycles,"),
            std::string::npos)
      << "a misspelt metric compares n/a with n/a and never catches a regression: " << e;
  e = error_of(
      [&] { read_regress_suite(write("r.toml", suite("\"type.gi.l1_hit_rate\" = 0.1\n"))); });
  EXPECT_NE(e.find("line 5: [tolerance] unknown ray type 'gi'"), std::string::npos) << e;
  e = error_of([&] {
    read_regress_suite(write("r.toml", suite("\"type.*.l1_hitrate\" = { absolute = 0.1 }\n")));
  });
  EXPECT_NE(e.find("line 5: [tolerance] unknown metric 'type.*.l1_hitrate' (per ray type"),
            std::string::npos)
      << e;
  EXPECT_EQ(error_of([&] {
              read_regress_suite(write("r.toml", suite("\"type.diffuse_gi.latency_p99\" = 0.1\n"
                                                       "\"type.*.rays\" = 0\n")));
            }),
            "");
}

TEST(RegressSuite, ReadsCasesDefaultsAndTolerances) {
  RegressSuite s = read_regress_suite(write("r.toml", R"(config = "hw.toml"
[defaults]
resolution = "32x18"
[[case]]
name = "a"
[[case]]
name = "b"
workload = "cornell"
set = ["rt.count=2"]
[tolerance]
cycles = 0.02
l1_hit_rate = { absolute = 0.01, direction = "higher" }
)"));
  ASSERT_EQ(s.cases.size(), 2u);
  EXPECT_EQ(s.cases[0].trace.resolution, "32x18") << "defaults apply to every case";
  EXPECT_EQ(s.cases[1].sets, std::vector<std::string>{"rt.count=2"});
  ASSERT_EQ(s.tolerances.size(), 2u);
  EXPECT_DOUBLE_EQ(s.tolerances[0].relative, 0.02);
  EXPECT_DOUBLE_EQ(s.tolerances[1].absolute, 0.01);
  EXPECT_EQ(s.tolerances[1].direction, "higher");
  EXPECT_NE(error_of([] {
              read_regress_suite(write("r.toml", "[[case]]\nname = \"a\"\n"));
            }).find("tolerance"),
            std::string::npos)
      << "a suite must say what it compares";
  const std::string tolerance = "[tolerance]\ncycles = 0.02\n";
  EXPECT_NE(error_of([&] {
              read_regress_suite(
                  write("r.toml", "[defaults]\nresolutoin = \"8x8\"\n[[case]]\n" + tolerance));
            }).find("line 2: unknown key 'resolutoin' in [defaults]"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              read_regress_suite(write("r.toml", "[[case]]\nframes = \"2\"\n" + tolerance));
            }).find("line 2: 'frames' must be an integer"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              read_regress_suite(write("r.toml", "verify = 1\n[[case]]\n" + tolerance));
            }).find("line 1: 'verify' must be true or false"),
            std::string::npos);
}

}  // namespace
}  // namespace rtsim::reports
