// `rtsim sweep` over 8 points: it finishes with the CSV, JSON, charts and pages; killed half
// way it resumes without redoing finished points; with some results deleted it redoes only
// those. Killed with SIGKILL its `rtsim run` children end too, and a second sweep on a folder in
// use is refused (issue 16, defect 9).
#include <gtest/gtest.h>

#include <fmt/core.h>

#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <thread>

#include "reports/sweep_runner.h"
#include "tests/reports/report_test_util.h"

namespace rtsim {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

std::string spec() {
  return test::source_path("tests/reports/sweep-tiny.toml");
}

std::map<std::string, fs::file_time_type> finished_points(const std::string& dir) {
  std::map<std::string, fs::file_time_type> out;
  if (!fs::exists(dir + "/points")) return out;
  for (const auto& entry : fs::directory_iterator(dir + "/points"))
    if (fs::exists(entry.path() / "report.json"))
      out[entry.path().filename()] = fs::last_write_time(entry.path() / "report.json");
  return out;
}

TEST(Sweep, FinishesWithCsvJsonChartsAndPages) {
  std::string dir = test::shared_run("sweep", "sweep " + spec() + " -j 2");
  ASSERT_FALSE(dir.empty()) << "rtsim sweep failed";
  Json doc = test::read_json(dir + "/sweep.json");
  ASSERT_EQ(doc["points"].size(), 8u);
  for (const Json& p : doc["points"]) {
    EXPECT_EQ(p["status"], "done") << p["id"];
    EXPECT_GT(p["metrics"]["cycles"].get<double>(), 0) << p["id"];
  }
  std::string csv = test::slurp(dir + "/sweep.csv");
  EXPECT_EQ(test::count_lines(csv), 9) << "a header and one row per point";
  EXPECT_EQ(csv.rfind("workload,id,status,ran_on,l2.size_bytes,rt.l1.size_bytes,", 0), 0u) << csv;
  for (const Json& p : doc["points"]) {
    std::string row =
        fmt::format("{},{},done,local on {},{},{},", p["workload"].get<std::string>(),
                    p["id"].get<std::string>(), reports::host_name(),
                    p["values"]["l2.size_bytes"].dump(), p["values"]["rt.l1.size_bytes"].dump());
    EXPECT_NE(csv.find("\n" + row), std::string::npos) << "the swept values of " << p["id"];
  }
  std::string html = test::slurp(dir + "/sweep.html");
  std::vector<test::Figure> figures = test::figures(html);
  ASSERT_EQ(figures.size(), doc["charts"].size());
  bool pareto = false;
  for (const Json& c : doc["charts"]) {
    EXPECT_TRUE(c["available"].get<bool>()) << c["id"] << ": " << c["reason"];
    std::string png = test::slurp(dir + "/" + c["file"].get<std::string>());
    EXPECT_EQ(png.substr(1, 3), "PNG") << c["file"];
    pareto |= c["kind"] == "pareto";
  }
  EXPECT_TRUE(pareto) << "the Pareto charts of cycles against on-chip memory, area and energy";
  EXPECT_GE(doc["charts"].size(), 5u) << "curves of cycles and DRAM bytes per ray, and Pareto";
  EXPECT_NE(csv.find(",energy_nj_per_ray,mrays_per_joule,power_w,area_mm2,sram_area_mm2,"),
            std::string::npos)
      << "energy and area in the CSV";
  // The objective: least energy per ray within 0.05 mm² of SRAM, which rules out points.
  const Json* pick = nullptr;
  size_t excluded = 0;
  for (const Json& p : doc["points"]) {
    const Json& m = p["metrics"];
    if (m["sram_area_mm2"].get<double>() > 0.05) {
      ++excluded;
      continue;
    }
    if (!pick || m["energy_nj_per_ray"].get<double>() <
                     (*pick)["metrics"]["energy_nj_per_ray"].get<double>())
      pick = &p;
  }
  ASSERT_NE(pick, nullptr);
  EXPECT_GT(excluded, 0u);
  const Json& best = doc["objective"]["best"][0];
  EXPECT_EQ(best["id"], (*pick)["id"]);
  EXPECT_EQ(best["value"], (*pick)["metrics"]["energy_nj_per_ray"]);
  EXPECT_LE(best["bounded_metrics"]["sram_area_mm2"].get<double>(), 0.05);
  EXPECT_NE(html.find("<section id=\"objective\">"), std::string::npos);
  EXPECT_NE(test::slurp(dir + "/sweep.md").find("## Objective\n\n- pica: energy_nj_per_ray"),
            std::string::npos);
  for (const test::Cell& c : test::number_cells(html))
    EXPECT_EQ(Json::parse(c.value), reports::at_key(doc, c.key)) << c.key;
}

TEST(Sweep, ResumesAfterBeingKilledWithoutRedoingPoints) {
  std::string dir = test::fresh_dir("sweep-killed");
  pid_t pid = fork();
  if (pid == 0) {
    setpgid(0, 0);
    execl(RTSIM_EXE, RTSIM_EXE, "sweep", spec().c_str(), "-o", dir.c_str(), "-j", "1", "-q",
          "--no-charts", nullptr);
    _exit(127);
  }
  setpgid(pid, pid);
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (finished_points(dir).size() < 2 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  kill(-pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  auto before = finished_points(dir);
  ASSERT_GE(before.size(), 2u) << "two points finished before the kill";
  ASSERT_LT(before.size(), 8u) << "the kill came before the end";
  test::RunResult r = test::run_rtsim("sweep " + spec() + " -o " + dir + " -j 2 --no-charts");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find(std::to_string(before.size()) + " done before"), std::string::npos) << r.out;
  auto after = finished_points(dir);
  EXPECT_EQ(after.size(), 8u);
  for (const auto& [id, time] : before) EXPECT_EQ(after[id], time) << id << " was not redone";
  EXPECT_EQ(test::count_lines(test::slurp(dir + "/sweep.csv")), 9);
  fs::remove_all(dir);
}

// Starts `rtsim sweep -j 2` of points that take seconds into dir, in its own process group.
pid_t start_sweep(const std::string& dir) {
  std::string slow = test::source_path("tests/reports/sweep-slow.toml");
  pid_t pid = fork();
  if (pid == 0) {
    setpgid(0, 0);
    execl(RTSIM_EXE, RTSIM_EXE, "sweep", slow.c_str(), "-o", dir.c_str(), "-j", "2", "-q",
          "--no-charts", nullptr);
    _exit(127);
  }
  setpgid(pid, pid);
  return pid;
}

// The processes whose parent is `parent` (from /proc).
std::set<pid_t> children_of(pid_t parent) {
  std::set<pid_t> out;
  for (const auto& entry : fs::directory_iterator("/proc")) {
    std::string name = entry.path().filename();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream stat(entry.path() / "stat");
    std::string line;
    std::getline(stat, line);
    size_t close = line.rfind(')');  // the command name may hold spaces
    if (close == std::string::npos) continue;
    char state = 0;
    int ppid = 0;
    if (sscanf(line.c_str() + close + 1, " %c %d", &state, &ppid) == 2 && ppid == parent &&
        state != 'Z')
      out.insert(pid_t(std::stoi(name)));
  }
  return out;
}

bool running(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return false;
  size_t close = line.rfind(')');
  return close != std::string::npos && line.size() > close + 2 && line[close + 2] != 'Z';
}

TEST(Sweep, ItsChildrenEndWhenItIsKilled) {
  std::string dir = test::fresh_dir("sweep-orphans");
  pid_t pid = start_sweep(dir);
  std::set<pid_t> children;
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (children.empty() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    children = children_of(pid);
  }
  ASSERT_FALSE(children.empty()) << "the sweep started no child";
  kill(pid, SIGKILL);  // the sweep alone, as the OOM killer would
  waitpid(pid, nullptr, 0);
  // A point takes seconds; ended with their parent, the children are gone well before.
  deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(1500);
  auto alive = [&] {
    int n = 0;
    for (pid_t c : children) n += running(c);
    return n;
  };
  while (alive() > 0 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(alive(), 0) << "children outlived the sweep";
  kill(-pid, SIGKILL);  // whatever is left, so the test cleans up either way
  fs::remove_all(dir);
}

TEST(Sweep, ASecondSweepOnAFolderInUseIsRefused) {
  std::string dir = test::fresh_dir("sweep-twice");
  pid_t pid = start_sweep(dir);
  std::string owner = std::to_string(pid) + "\n";
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (test::slurp(dir + "/.rtsim.lock") != owner && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  test::RunResult r =
      test::run_rtsim("sweep " + test::source_path("tests/reports/sweep-slow.toml") + " -o " + dir +
                      " -q --no-charts");
  kill(-pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_EQ(r.err, "rtsim: error: " + dir + ": another rtsim (pid " + std::to_string(pid) +
                       ") is writing this folder; wait for it to finish, or give rtsim sweep "
                       "another -o\n");
  fs::remove_all(dir);
}

TEST(Sweep, RedoesOnlyThePointsWhoseResultsAreMissing) {
  std::string done = test::shared_run("sweep", "sweep " + spec() + " -j 2");
  ASSERT_FALSE(done.empty());
  std::string dir = test::fresh_dir("sweep-partial");
  fs::copy(done, dir, fs::copy_options::recursive);
  auto before = finished_points(dir);
  std::vector<std::string> removed;
  for (const auto& [id, time] : before)
    if (removed.size() < 3) {
      fs::remove(dir + "/points/" + id + "/report.json");
      removed.push_back(id);
    }
  test::RunResult r = test::run_rtsim("sweep " + spec() + " -o " + dir + " -j 2 --no-charts");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("5 done before, 3 to run"), std::string::npos) << r.out;
  EXPECT_LT(r.out.find("sweep      tiny: 8 configs x 1 workload; tracing the workloads"),
            r.out.find("5 done before"))
      << "planning says what it does before it counts: " << r.out;
  EXPECT_NE(r.out.find("trace      reusing "), std::string::npos) << r.out;
  auto after = finished_points(dir);
  EXPECT_EQ(after.size(), 8u);
  for (const auto& [id, time] : before)
    if (std::find(removed.begin(), removed.end(), id) == removed.end()) {
      EXPECT_EQ(after[id], time) << id << " was not redone";
    }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rtsim
