// Output paths that are not regular files (issue 16, defect 1): a character device given as
// `-o` stays a device, a symbolic link stays a link and the file it names gets the output, and
// a regular file is still replaced whole. Temporaries never outlive their process (defect 8):
// SIGINT and SIGTERM remove them, and those of dead processes are removed by the next writer.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "tests/cli/run_rtsim.h"

namespace rtsim {
namespace {

namespace fs = std::filesystem;

class CliOutputs : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rtsim-outputs-" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(CliOutputs, ACharacterDeviceStaysADevice) {
  std::string null = path("null");
  if (mknod(null.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0)
    GTEST_SKIP() << "making a device node needs root";
  test::RunResult r = test::run_rtsim("trace cornell --resolution 16x9 -q -o " + null);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  struct stat info {};
  ASSERT_EQ(stat(null.c_str(), &info), 0);
  EXPECT_TRUE(S_ISCHR(info.st_mode)) << "rtsim replaced the device with a regular file";
  EXPECT_EQ(fs::directory_iterator(dir_)->path().filename(), "null") << "no temporary left";
}

TEST_F(CliOutputs, AFifoIsRefusedForAStreamWithoutWaitingForAReader) {
  std::string fifo = path("fifo");
  ASSERT_EQ(mkfifo(fifo.c_str(), 0666), 0);
  test::RunResult r = test::run_rtsim("trace cornell --resolution 16x9 -q -o " + fifo);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("rtsim: error: " + fifo + ": cannot write a ray stream to a FIFO", 0), 0u)
      << r.err;
  EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST_F(CliOutputs, ASymlinkStaysALinkAndItsFileGetsTheOutput) {
  std::string real = path("real.rays"), link = path("link.rays");
  fs::create_symlink(real, link);
  test::RunResult r = test::run_rtsim("trace cornell --resolution 16x9 -q -o " + link);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_TRUE(fs::is_regular_file(real));
  test::RunResult info = test::run_rtsim("trace-info " + link);
  EXPECT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("144"), std::string::npos) << "16x9 camera rays:\n" << info.out;
}

TEST_F(CliOutputs, ARegularFileIsReplacedWhole) {
  std::string file = path("s.rays");
  std::ofstream(file) << "old contents";
  test::RunResult r = test::run_rtsim("trace cornell --resolution 16x9 -q -o " + file);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::run_rtsim("trace-info " + file).exit_code, 0);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1)
      << "no temporary file left beside it";
}

// Starts `rtsim trace` of a 3-frame 1080p workload into out, waits until its temporary
// appears, sends `signal_number` and returns how the process ended (its wait status).
int interrupt_a_trace(const std::string& out, int signal_number, std::string& temporary) {
  pid_t pid = fork();
  if (pid == 0) {
    execl(RTSIM_EXE, RTSIM_EXE, "trace", "cornell", "--frames", "3", "-q", "-o", out.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  temporary = out + ".tmp-" + std::to_string(pid);
  for (int i = 0; i < 3000 && !fs::exists(temporary); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_TRUE(fs::exists(temporary)) << "the trace never started writing";
  kill(pid, signal_number);
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

TEST_F(CliOutputs, SigintAndSigtermRemoveTheTemporaryAndEndTheProcessBySignal) {
  for (int signal_number : {SIGINT, SIGTERM}) {
    std::string temporary;
    int status = interrupt_a_trace(path("big.rays"), signal_number, temporary);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal_number) << status;
    EXPECT_FALSE(fs::exists(temporary)) << temporary;
    EXPECT_FALSE(fs::exists(path("big.rays")));
  }
}

TEST_F(CliOutputs, TemporariesOfDeadProcessesAreRemovedByTheNextWriter) {
  pid_t dead = fork();
  if (dead == 0) _exit(0);
  waitpid(dead, nullptr, 0);
  std::string file = path("s.rays");
  std::string stale = file + ".tmp-" + std::to_string(dead);
  std::string live = file + ".tmp-" + std::to_string(getpid());  // this test: still running
  std::ofstream(stale) << "left by a kill -9";
  std::ofstream(live) << "being written";
  test::RunResult r = test::run_rtsim("trace cornell --resolution 16x9 -q -o " + file);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(live)) << "a running process's temporary is left alone";
}

}  // namespace
}  // namespace rtsim
