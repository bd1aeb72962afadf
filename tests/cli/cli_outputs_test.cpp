// Output paths that are not regular files (issue 16, defect 1): a character device given as
// `-o` stays a device, a symbolic link stays a link and the file it names gets the output, and
// a regular file is still replaced whole.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <filesystem>

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

}  // namespace
}  // namespace rtsim
