// rtsim-noimage (app/noimage_main.cpp): bench-sim as rtsim runs it, in the executable that
// valgrind can run, with rtsim's handling of bad input.
#include <gtest/gtest.h>

#include <regex>

#include "run_rtsim.h"

namespace rtsim::test {
namespace {

// "N cycles, M DRAM B/ray" of bench-sim's sim line.
std::string simulated(const std::string& out) {
  std::smatch m;
  return std::regex_search(out, m, std::regex(R"(\d+ cycles, \d+ DRAM B/ray)")) ? m.str() : "";
}

TEST(CliNoImage, BenchSimSimulatesWhatRtsimDoes) {
  const std::string args = "bench-sim --scene grid:3000 --rays 2000 --repeat 1 --no-embree";
  RunResult noimage = run_program(RTSIM_NOIMAGE_EXE, args);
  RunResult rtsim = run_rtsim(args);
  ASSERT_EQ(noimage.exit_code, 0) << noimage.err;
  ASSERT_EQ(rtsim.exit_code, 0) << rtsim.err;
  EXPECT_NE(simulated(noimage.out), "") << noimage.out;
  EXPECT_EQ(simulated(noimage.out), simulated(rtsim.out));
}

TEST(CliNoImage, BadInputIsOneLineAndExitTwo) {
  for (const char* args : {"", "bench-sim --rays -3", "bench-sim --scene missing.obj",
                           "bench-sim --scene grid:300 --set rt.count=0", "sim"}) {
    RunResult r = run_program(RTSIM_NOIMAGE_EXE, args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << args << ": " << r.err;
  }
}

}  // namespace
}  // namespace rtsim::test
