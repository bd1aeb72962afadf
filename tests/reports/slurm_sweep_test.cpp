// `rtsim sweep --engine slurm` (issue 19). On a real single-node Slurm (scripts/slurm-local):
// 8 points in 4 array tasks after a trace job; one running task is cancelled with scancel,
// --status shows its unfinished point failed and nothing partial is left, a re-submission
// runs only what is missing, --collect writes the pages, and every point is bit-identical to a
// local sweep of the same spec. Skips, saying why, when Slurm cannot be started here. Without
// Slurm: --dry-run writes the scripts, and bad input ends with one line and exit 2.
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <thread>

#include "tests/reports/report_test_util.h"

namespace rtsim {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;

std::string spec() {
  return test::source_path("tests/reports/sweep-slurm.toml");
}

struct Shell {
  int exit_code = -1;
  std::string out;
};

Shell shell(const std::string& command) {
  Shell r;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) r.out.append(buffer, n);
  int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// The files of each point folder, by point id.
std::map<std::string, std::set<std::string>> point_files(const std::string& dir) {
  std::map<std::string, std::set<std::string>> out;
  for (const auto& point : fs::directory_iterator(dir + "/points"))
    for (const auto& file : fs::recursive_directory_iterator(point.path()))
      out[point.path().filename()].insert(fs::relative(file.path(), point.path()).string());
  return out;
}

// stats.json without what differs between two runs of the same point: the host's time and the
// stream's path.
Json model_stats(const std::string& point_dir) {
  Json stats = test::read_json(point_dir + "/stats.json");
  stats.erase("host");
  stats["input"].erase("stream");
  return stats;
}

class SlurmSweep : public ::testing::Test {
 protected:
  void SetUp() override {
    if (geteuid() != 0) GTEST_SKIP() << "needs root to start a local Slurm (slurmd)";
    for (const char* tool : {"slurmctld", "slurmd", "munged", "sbatch", "squeue", "scancel"})
      if (shell(std::string("command -v ") + tool).exit_code != 0)
        GTEST_SKIP() << tool << " is not installed (scripts/install-deps --slurm)";
    slurm_dir_ = test::fresh_dir("slurm-local");
    Shell start = shell(test::source_path("scripts/slurm-local") + " start " + slurm_dir_);
    if (start.exit_code != 0) GTEST_SKIP() << "the local Slurm did not start: " << start.out;
    setenv("SLURM_CONF", (slurm_dir_ + "/slurm.conf").c_str(), 1);
  }
  void TearDown() override {
    if (!slurm_dir_.empty())
      shell(test::source_path("scripts/slurm-local") + " stop " + slurm_dir_);
  }

  // --status until no task of the sweep is running or pending.
  std::string wait_for_queue(const std::string& dir) {
    auto deadline = Clock::now() + std::chrono::seconds(300);
    test::RunResult status;
    while (Clock::now() < deadline) {
      status = test::run_rtsim("sweep --status " + dir);
      if (status.out.find(" 0 running, 0 pending,") != std::string::npos) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
    return status.out;
  }

  std::string slurm_dir_;
};

TEST_F(SlurmSweep, CancelledResumedCollectedAndIdenticalToALocalSweep) {
  std::string dir = test::fresh_dir("sweep-slurm");
  test::RunResult submit =
      test::run_rtsim("sweep " + spec() + " -o " + dir + " --engine slurm --points-per-task 2");
  ASSERT_EQ(submit.exit_code, 0) << submit.out << submit.err;
  EXPECT_NE(submit.out.find("8 points, 0 done, 0 queued, 8 to submit"), std::string::npos)
      << submit.out;
  EXPECT_NE(submit.out.find("(4 tasks, after trace job"), std::string::npos) << submit.out;
  test::RunResult local_meanwhile = test::run_rtsim("sweep " + spec() + " -o " + dir + " -q");
  EXPECT_EQ(local_meanwhile.exit_code, 2) << "a local sweep on a folder with queued Slurm jobs";
  EXPECT_NE(local_meanwhile.err.find("still queued or running"), std::string::npos)
      << local_meanwhile.err;

  // Cancel the task of a point while its `rtsim run` runs (where.json, no report.json yet); if
  // the point finishes before the signal lands, try the next one.
  std::string cancelled_point;
  auto deadline = Clock::now() + std::chrono::seconds(300);
  std::set<std::string> tried;
  while (cancelled_point.empty() && Clock::now() < deadline) {
    for (const auto& point : fs::directory_iterator(dir + "/points")) {
      std::string where = point.path() / "where.json";
      if (!fs::exists(where) || fs::exists(point.path() / "report.json")) continue;
      std::string job = test::read_json(where)["job"].get<std::string>();
      if (tried.count(job)) continue;
      tried.insert(job);
      shell("scancel " + job);
      std::this_thread::sleep_for(std::chrono::seconds(1));
      if (!fs::exists(point.path() / "report.json")) cancelled_point = point.path().filename();
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_FALSE(cancelled_point.empty()) << "no task was caught while it ran";

  std::string status = wait_for_queue(dir);
  EXPECT_NE(status.find(cancelled_point + " "), std::string::npos) << status;
  size_t line = status.find(cancelled_point);
  EXPECT_NE(status.find("failed", line), std::string::npos) << status;
  EXPECT_NE(status.find("cancelled or killed while running", line), std::string::npos) << status;
  EXPECT_EQ(status.find(" 0 failed"), std::string::npos) << status;
  for (const auto& [id, files] : point_files(dir)) {
    if (files.count("report.json")) continue;
    for (const std::string& f : files) {
      EXPECT_TRUE(f == "request.json" || f == "where.json" || f == "run.log")
          << id << " was left with " << f;
    }
  }

  test::RunResult resume =
      test::run_rtsim("sweep " + spec() + " -o " + dir + " --engine slurm --points-per-task 2");
  ASSERT_EQ(resume.exit_code, 0) << resume.out << resume.err;
  EXPECT_NE(resume.out.find(", 0 queued, "), std::string::npos) << resume.out;
  EXPECT_EQ(resume.out.find(", 0 to submit"), std::string::npos) << resume.out;
  EXPECT_EQ(resume.out.find("trace job"), std::string::npos) << "the traces are made once";
  status = wait_for_queue(dir);
  EXPECT_NE(status.find("8 done, 0 running, 0 pending, 0 failed"), std::string::npos) << status;

  test::RunResult collect = test::run_rtsim("sweep --collect " + dir + " --no-charts");
  ASSERT_EQ(collect.exit_code, 0) << collect.out << collect.err;
  Json slurm = test::read_json(dir + "/sweep.json");
  ASSERT_EQ(slurm["points"].size(), 8u);
  for (const Json& p : slurm["points"]) {
    EXPECT_EQ(p["status"], "done") << p["id"];
    EXPECT_EQ(p["ran_on"].get<std::string>().rfind("slurm job ", 0), 0u) << p["ran_on"];
  }

  std::string local_dir = test::fresh_dir("sweep-slurm-local");
  test::RunResult local =
      test::run_rtsim("sweep " + spec() + " -o " + local_dir + " -j 2 -q --no-charts");
  ASSERT_EQ(local.exit_code, 0) << local.out << local.err;
  auto slurm_files = point_files(dir), local_files = point_files(local_dir);
  ASSERT_EQ(slurm_files, local_files) << "the same points, each with the same files";
  for (const auto& [id, files] : local_files) {
    std::string a = dir + "/points/" + id, b = local_dir + "/points/" + id;
    EXPECT_EQ(model_stats(a), model_stats(b)) << id;
    for (const std::string& f : files) {
      bool exact = f.find(".f32") != std::string::npos || f == "config.toml" || f == "request.json";
      if (!exact) continue;
      EXPECT_EQ(test::slurp(a + "/" + f), test::slurp(b + "/" + f)) << id << "/" << f;
    }
  }
  fs::remove_all(dir);
  fs::remove_all(local_dir);
}

TEST(SlurmSweepScripts, DryRunWritesAndPrintsTheJobScriptsWithoutSubmitting) {
  std::string dir = test::fresh_dir("sweep-slurm-dry");
  test::RunResult r = test::run_rtsim(
      "sweep " + spec() + " -o " + dir +
      " --engine slurm --dry-run --partition arch --time 30 --mem 4G --cpus-per-task 2"
      " --array-limit 3 --points-per-task 3 --sbatch-arg=--account=rt");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  std::string points = test::slurp(dir + "/slurm/submit-1/points.sh");
  for (const char* line :
       {"#SBATCH --array=0-2%3\n", "#SBATCH --partition=arch\n", "#SBATCH --time=30\n",
        "#SBATCH --mem=4G\n", "#SBATCH --cpus-per-task=2\n", "#SBATCH --account=rt\n",
        " sweep --slurm-task "})
    EXPECT_NE(points.find(line), std::string::npos) << line << " in\n" << points;
  std::string trace = test::slurp(dir + "/slurm/submit-1/trace.sh");
  EXPECT_NE(trace.find(" --trace-only --max-points 10000\n"), std::string::npos) << trace;
  EXPECT_NE(r.out.find(points), std::string::npos) << "the scripts are printed";
  EXPECT_NE(r.out.find("--dependency=afterok:"), std::string::npos) << r.out;
  Json tasks = test::read_json(dir + "/slurm/submit-1/tasks.json");
  ASSERT_EQ(tasks["tasks"].size(), 3u);
  EXPECT_EQ(tasks["tasks"][2].size(), 2u) << "8 points in tasks of 3, 3 and 2";
  EXPECT_FALSE(fs::exists(dir + "/slurm/state.json")) << "nothing was submitted";
  EXPECT_FALSE(fs::exists(dir + "/points")) << "no point was touched";
  fs::remove_all(dir);
}

TEST(SlurmSweepScripts, BadInputEndsWithOneLineAndExit2) {
  std::string dir = test::fresh_dir("sweep-slurm-bad");
  std::string no_slurm = test::fresh_dir("sweep-slurm-empty-path");
  struct Case {
    std::string args, says;
  } cases[] = {
      {"sweep " + spec() + " -o " + dir + " --engine lsf", "--engine: lsf not in {local,slurm}"},
      {"sweep " + spec() + " -o /proc/rtsim-sweep --engine slurm", "cannot create the output"},
      {"sweep " + spec() + " -o " + dir + " --partition arch", "an option of --engine slurm"},
      {"sweep --status " + dir, "not a Slurm sweep folder"},
      {"sweep --collect " + dir, "not a Slurm sweep folder"},
      {"sweep " + spec() + " -o '" + dir + " 2' --engine slurm --dry-run",
       "which a Slurm job script cannot carry"},
      {"sweep " + spec() + " -o " + dir + " --engine slurm --dry-run --sbatch-arg=--array=0-3",
       "rtsim sets that option itself"},
      {"sweep " + spec() + " -o " + dir + " --engine slurm -j 4", "an option of the local engine"},
      {"sweep " + spec() + " -o " + dir + " --status " + dir, "give one of SPEC, --status"},
  };
  for (const Case& c : cases) {
    test::RunResult r = test::run_rtsim(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args;
    EXPECT_EQ(test::count_lines(r.err), 1) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << ": " << r.err;
  }
  Shell r = shell("PATH=" + no_slurm + " " + RTSIM_EXE + " sweep " + spec() + " -o " + dir +
                  " --engine slurm");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(test::count_lines(r.out), 1) << r.out;
  EXPECT_NE(r.out.find("sbatch not found on PATH"), std::string::npos) << r.out;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rtsim
