// `rtsim run` on the built-in pica scene at a tiny resolution: the report has every section the
// issue lists, every number on the page is the JSON's, every image is named and shown, and the
// charts are reproducible byte for byte.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <thread>

#include "reports/report_doc.h"
#include "reports/report_pages.h"
#include "tests/reports/report_test_util.h"

namespace rtsim {
namespace {

using Json = nlohmann::ordered_json;

class RunReport : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::shared_run(
        "run", "run pica --resolution 64x36 --config " + test::source_path("configs/mobile.toml"));
    ASSERT_FALSE(dir_.empty()) << "rtsim run failed";
    report_ = test::read_json(dir_ + "/report.json");
    html_ = test::slurp(dir_ + "/report.html");
    markdown_ = test::slurp(dir_ + "/report.md");
  }
  std::string dir_, html_, markdown_;
  Json report_;
};

TEST(OnChipBytes, TreeletModeCountsTheRayBuffersSram) {
  HwConfig c;
  double depth_first = reports::on_chip_bytes(c);
  c.rt.mode = TraversalMode::Treelet;
  c.treelet_queues.buffer.bytes = 65536;
  uint32_t state = ray_state_bytes(c.rt.stack);
  EXPECT_EQ(reports::on_chip_bytes(c), depth_first + 65536)
      << "the SRAM, used to the last byte or not";
  c.treelet_queues.buffer.bytes = 0;
  EXPECT_EQ(reports::on_chip_bytes(c), depth_first + double(c.treelet_queues.max_rays) * state);
  c.treelet_queues.buffer.place = RayBufferPlace::Memory;
  EXPECT_EQ(reports::on_chip_bytes(c), depth_first);
}

TEST(OnChipBytes, ASortingUnitCountsItsBuffer) {
  HwConfig c;
  double plain = reports::on_chip_bytes(c);
  c.sort.buffer_rays = 4096;
  EXPECT_EQ(reports::on_chip_bytes(c), plain) << "key none: no sorting unit";
  c.sort.key = SortKey::Hash;
  EXPECT_EQ(reports::on_chip_bytes(c), plain + 4096.0 * 40);
}

TEST_F(RunReport, HasEverySection) {
  for (const char* id : {"summary", "workload", "hardware", "timing", "bandwidth", "energy",
                         "coherence", "verification", "pictures", "charts"})
    EXPECT_NE(html_.find(std::string("<section id=\"") + id + "\">"), std::string::npos) << id;
  for (const char* heading :
       {"## Workload", "## Hardware config", "## Timing", "## Bandwidth", "## Energy and area",
        "## Coherence", "## Verification", "## Pictures and charts"})
    EXPECT_NE(markdown_.find(heading), std::string::npos) << heading;
  EXPECT_EQ(report_["workload"]["scene"], "builtin:pica");
  EXPECT_EQ(report_["workload"]["triangles"], 4328);
  EXPECT_GT(report_["workload"]["rays_per_type"]["camera"].get<int>(), 0);
  EXPECT_EQ(report_["workload"]["passes"].size(), 9u) << "every pass, skipped or not";
  for (const Json& pass : report_["workload"]["passes"]) {
    if (pass["skipped"].get<bool>()) {
      EXPECT_FALSE(pass["reason"].get<std::string>().empty()) << "a skipped pass says why";
    }
    EXPECT_LE(pass["alpha_rays"].get<uint64_t>(), pass["rays"].get<uint64_t>()) << pass["pass"];
  }
  EXPECT_EQ(report_["hardware"]["name"], "mobile");
  EXPECT_GT(report_["timing"]["cycles"].get<double>(), 0);
  EXPECT_NEAR(report_["timing"]["mrays_per_second"].get<double>(),
              report_["timing"]["rays"].get<double>() / report_["timing"]["cycles"].get<double>() *
                  report_["timing"]["clock_ghz"].get<double>() * 1e3,
              1e-6)
      << "MRays/s at the configured clock";
  for (const char* level :
       {"l1_bytes_per_ray", "l2_bytes_per_ray", "dram_bytes_per_ray", "dram_utilisation"})
    EXPECT_TRUE(report_["bandwidth"][level].is_number()) << level;
  EXPECT_TRUE(report_["coherence"]["nodes_per_ray"].is_number());
  const Json& energy = report_["energy"];
  EXPECT_NEAR(
      energy["mrays_per_joule"].get<double>(),
      report_["timing"]["rays"].get<double>() / (energy["total_nj"].get<double>() * 1e-9) / 1e6,
      1e-6)
      << "the stats JSON's energy, rays per joule";
  for (const auto& [type, rays] : report_["workload"]["rays_per_type"].items()) {
    if (rays.get<uint64_t>() == 0) continue;
    EXPECT_GT(energy["by_type"][type]["dynamic_nj_per_ray"].get<double>(), 0) << type;
  }
  EXPECT_TRUE(report_["verification"]["passed"].get<bool>());
  EXPECT_NE(html_.find("PASSED"), std::string::npos);
  // 64x36 keeps GI's rays a frame: the workload section says what that makes of the mix.
  EXPECT_NE(markdown_.find("| ray mix | ray mix at 64x36 is not the 1920x1080 one the budgets "
                           "are set for: budget rays a pixel diffuse_gi 109 against 0.121 (900x)"),
            std::string::npos)
      << markdown_;
}

TEST_F(RunReport, EveryNumberOnThePageIsTheJsons) {
  std::vector<test::Cell> cells = test::number_cells(html_);
  ASSERT_GT(cells.size(), 100u);
  for (const test::Cell& c : cells) {
    const Json& value = reports::at_key(report_, c.key);
    EXPECT_EQ(Json::parse(c.value), value) << c.key << " carries the JSON's value";
    if (value.is_number()) {
      std::string plain = c.shown;  // thousands are grouped: 11,603
      plain.erase(std::remove(plain.begin(), plain.end(), ','), plain.end());
      double shown = std::stod(plain);
      double v = value.get<double>() * (c.shown.back() == '%' ? 100.0 : 1.0);
      EXPECT_NEAR(shown, v, 1e-3 * std::abs(v) + 0.006) << c.key << " shows " << c.shown;
    }
  }
  for (const char* key :
       {"timing.cycles", "timing.mrays_per_second", "bandwidth.dram_bytes_per_ray",
        "verification.unexplained", "workload.triangles", "hardware.l2.size_bytes"}) {
    bool found = false;
    for (const test::Cell& c : cells) found |= c.key == key;
    EXPECT_TRUE(found) << key << " is on the page";
  }
  std::string cycles = reports::show(report_["timing"]["cycles"], reports::Style::Integer);
  EXPECT_NE(markdown_.find("| cycles | " + cycles + " |"), std::string::npos) << cycles;
}

TEST_F(RunReport, NamesAndShowsEveryImage) {
  std::vector<test::Figure> figures = test::figures(html_);
  ASSERT_EQ(figures.size(), report_["images"].size()) << "one figure per listed image";
  size_t charts = 0, heatmaps = 0;
  for (const Json& image : report_["images"]) {
    std::string id = image["id"], file = image["file"], title = image["title"];
    ASSERT_TRUE(image["available"].get<bool>()) << id << ": " << image["reason"];
    charts += image["kind"] == "chart";
    heatmaps += image["kind"] == "heatmap";
    std::string png = test::slurp(dir_ + "/" + file);
    ASSERT_EQ(png.substr(1, 3), "PNG") << file << " is a PNG";
    auto it = std::find_if(figures.begin(), figures.end(),
                           [&](const test::Figure& f) { return f.id == id; });
    ASSERT_NE(it, figures.end()) << id;
    EXPECT_EQ(it->base64, reports::base64(png)) << id << " is embedded as it is on disk";
    EXPECT_NE(it->caption.find(title), std::string::npos) << id << " is named";
    EXPECT_NE(it->caption.find(file), std::string::npos) << id << " names its file";
    EXPECT_NE(markdown_.find("![" + title + "](" + file + ")"), std::string::npos) << id;
  }
  EXPECT_EQ(charts, 4u) << "latency per ray type, hit rates, where the time went and the energy";
  EXPECT_EQ(heatmaps, 3u) << "cycles, nodes and DRAM bytes per pixel";
}

TEST_F(RunReport, ChartsAreReproducibleByteForByte) {
  std::string copy = test::fresh_dir("report-again");
  std::filesystem::copy(dir_, copy, std::filesystem::copy_options::recursive);
  test::RunResult r = test::run_rtsim("report " + copy);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const Json& image : report_["images"]) {
    std::string file = image["file"];
    EXPECT_EQ(test::slurp(copy + "/" + file), test::slurp(dir_ + "/" + file)) << file;
  }
  EXPECT_EQ(test::slurp(copy + "/report.html"), test::slurp(dir_ + "/report.html"));
  std::filesystem::remove_all(copy);
}

// The summary leads with what limits the design: the busiest resource, right after the names.
TEST_F(RunReport, LeadsWithWhatLimitsTheDesign) {
  std::string text = report_["timing"]["bottleneck"]["text"].get<std::string>();
  EXPECT_NE(text.find("% busy; next: "), std::string::npos) << text;
  size_t limit = markdown_.find("| what limits it (busiest resource) | " + text + " |");
  EXPECT_NE(limit, std::string::npos) << markdown_;
  EXPECT_LT(limit, markdown_.find("| cycles |")) << "before the numbers";
  EXPECT_LT(html_.find("what limits it"), html_.find("<section id=\"workload\">"));
  Json stats = test::read_json(dir_ + "/stats.json");
  double busiest = 0;
  for (const char* key : {"box", "triangle", "control", "l1_port"})
    busiest = std::max(busiest, stats["utilisation"]["mean"][key].get<double>());
  for (const char* key : {"dispatch", "l2_port", "xbar_busiest_link", "dram"})
    busiest = std::max(busiest, stats["utilisation"][key].get<double>());
  EXPECT_DOUBLE_EQ(report_["timing"]["bottleneck"]["utilisation"].get<double>(), busiest);
}

TEST_F(RunReport, AFullModelRunShowsNoIntervalRow) {
  EXPECT_EQ(report_["timing"]["cycles_ci95"], 0) << "the JSON keeps it";
  EXPECT_EQ(html_.find("95% interval"), std::string::npos) << "an exact run has no interval";
  EXPECT_EQ(markdown_.find("95% interval"), std::string::npos);
}

TEST(RunCommand, ASampledRunShowsItsInterval) {
  std::string dir = test::fresh_dir("sampled");
  test::RunResult r = test::run_rtsim(
      "run pica --resolution 64x36 --fidelity sampled --no-charts "
      "-q -o " +
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(test::slurp(dir + "/report.md").find("| cycles, 95% interval (±) | "),
            std::string::npos);
  std::filesystem::remove_all(dir);
}

// An instanced scene's report shows its two BVH levels; one level's shows none.
TEST(RunCommand, AForestRunReportsItsTwoLevels) {
  std::string dir = test::fresh_dir("forest");
  test::RunResult r = test::run_rtsim(
      "run pica --scene forest:100000 --resolution 64x36 --report json -q -o " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Json report = test::read_json(dir + "/report.json");
  EXPECT_GT(report["coherence"]["instances_per_ray"].get<double>(), 0.0);
  EXPECT_GT(report["coherence"]["tlas_nodes_per_ray"].get<double>(), 0.0);
  EXPECT_GT(report["coherence"]["blas_nodes_per_ray"].get<double>(), 0.0);
  std::string md = reports::report_markdown(report);
  EXPECT_NE(md.find("## Two BVH levels"), std::string::npos);
  EXPECT_NE(md.find("| TLAS L1 miss rate | "), std::string::npos) << md;
  std::string flat_dir = test::fresh_dir("forest-flat");
  test::RunResult flat = test::run_rtsim("run --from-trace " + dir +
                                         "/trace --flatten --report json -q -o " + flat_dir);
  ASSERT_EQ(flat.exit_code, 0) << flat.err;
  Json one = test::read_json(flat_dir + "/report.json");
  EXPECT_TRUE(one["coherence"]["instances_per_ray"].is_null());
  EXPECT_EQ(reports::report_markdown(one).find("## Two BVH levels"), std::string::npos);
  std::filesystem::remove_all(dir);
  std::filesystem::remove_all(flat_dir);
}

// The phases before the simulation say what they do: the trace's passes and the BVH build.
TEST(RunCommand, TheTraceAndBvhPhasesPrintProgress) {
  std::string dir = test::fresh_dir("progress");
  test::RunResult r = test::run_rtsim("run pica --resolution 16x9 --no-charts -o " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("trace      pica at 16x9, 1 frame(s), into " + dir + "/trace\n", 0), 0u)
      << r.out;
  for (const char* pass : {"camera", "shadow", "diffuse_gi", "translucency"})
    EXPECT_NE(r.err.find(std::string("trace: frame 1/1: ") + pass + "\n"), std::string::npos)
        << r.err;
  EXPECT_NE(r.err.find("bvh: building two levels, bvh8 aabb32 raw treelet"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find(" over 17 instances of 8 meshes (1488 unique, 4328 instanced "
                       "triangles)\nbvh: "),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find(" B a unique triangle), built in "), std::string::npos) << r.err;
  EXPECT_LT(r.err.find("bvh: building"), r.err.find("sim: ")) << r.err;
  std::filesystem::remove_all(dir);
}

TEST(RunCommand, BadInputIsOneLineAndExitTwo) {
  std::string dir = test::fresh_dir("bad");
  test::RunResult r = test::run_rtsim("run pica --resolution 16x9 --set rt.l1.bogus=1 -o " + dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bogus"), std::string::npos) << r.err;
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  std::filesystem::remove_all(dir);
}

TEST(RunCommand, AFromTraceRunRefusesWhatWouldTraceAnew) {
  std::string dir = test::fresh_dir("from-trace");
  for (const char* command :
       {"run pica", "run --resolution 8x8", "run --frames 2", "run --seed 3", "run --scene cornell",
        "speed-vs-error pica", "speed-vs-error --resolution 8x8", "run --fov 40",
        "run --camera-index 0"}) {
    std::string line = command;
    test::RunResult r = test::run_rtsim(line + " --from-trace " + dir + "/t -o " + dir + "/o");
    EXPECT_EQ(r.exit_code, 2) << command << "\n" << r.out << r.err;
    std::string sub = line.substr(0, line.find(' '));
    EXPECT_EQ(r.err.rfind("rtsim: error: " + sub + ": --from-trace " + dir +
                              "/t reuses that trace as it was traced; ",
                          0),
              0u)
        << command << ": " << r.err;
    EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  }
  std::filesystem::remove_all(dir);
}

TEST(RunCommand, AFolderNeverMixesTwoRuns) {
  namespace fs = std::filesystem;
  std::string dir = test::fresh_dir("rerun");
  ASSERT_EQ(test::run_rtsim("run cornell --resolution 16x9 --no-charts -q -o " + dir).exit_code, 0);
  ASSERT_TRUE(fs::exists(dir + "/report.html"));
  std::ofstream(dir + "/notes.txt") << "the user's own file";
  // A second run, interrupted while it traces: nothing of the first run is left beside it.
  pid_t pid = fork();
  if (pid == 0) {
    execl(RTSIM_EXE, RTSIM_EXE, "run", "pica", "--frames", "3", "-q", "-o", dir.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  std::string temporary = dir + "/trace/rays.rays.tmp-" + std::to_string(pid);
  for (int i = 0; i < 3000 && !fs::exists(temporary); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  kill(pid, SIGINT);
  waitpid(pid, nullptr, 0);
  for (const char* earlier :
       {"report.html", "report.json", "report.md", "stats.json", "fidelity.json", "config.toml",
        "pixel_cycles.f32", "images", "trace/rays.rays", "trace/trace.json", "trace/preview.png"})
    EXPECT_FALSE(fs::exists(dir + "/" + earlier)) << earlier << " of the first run is left";
  EXPECT_TRUE(fs::exists(dir + "/notes.txt")) << "files rtsim does not write stay";
  // A run that reuses the folder's own trace keeps it.
  ASSERT_EQ(test::run_rtsim("run cornell --resolution 16x9 --no-charts -q -o " + dir).exit_code, 0);
  test::RunResult again =
      test::run_rtsim("run --from-trace " + dir + "/trace --no-charts -q -o " + dir);
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_TRUE(fs::exists(dir + "/trace/rays.rays"));
  EXPECT_TRUE(fs::exists(dir + "/report.html"));
  fs::remove_all(dir);
}

TEST(OutputFolders, AnUnusableOutputFolderIsBadInputBeforeAnyWork) {
  std::string dir = test::fresh_dir("outputs");
  std::ofstream(dir + "/file") << "a file, not a folder";
  std::ofstream(dir + "/suite.toml") << "[[case]]\nname = \"pica\"\nresolution = \"8x8\"\n"
                                        "[tolerance]\ncycles = 0.02\n";
  const std::string bad = dir + "/file/out";
  const std::string sweep = test::source_path("tests/reports/sweep-tiny.toml");
  const std::string devices = test::source_path("configs/multi/four-mobile.toml");
  for (const std::string& command :
       {"sweep " + sweep + " -o " + bad,
        "regress " + dir + "/suite.toml --baseline " + dir + "/b --update-baseline -o " + bad,
        "regress " + dir + "/suite.toml --baseline " + bad + " --update-baseline -o " + dir + "/o",
        "multi-device pica --resolution 8x8 --devices-file " + devices + " -o " + bad,
        "speed-vs-error pica --resolution 8x8 -o " + bad, "run pica --resolution 8x8 -o " + bad}) {
    test::RunResult r = test::run_rtsim(command);
    EXPECT_EQ(r.exit_code, 2) << command << "\n" << r.out << r.err;
    EXPECT_EQ(r.err.rfind("rtsim: error: " + bad + ": cannot create the output folder", 0), 0u)
        << command << ": " << r.err;
    EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
    EXPECT_EQ(r.out.find("case "), std::string::npos) << "no case ran: " << r.out;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rtsim
