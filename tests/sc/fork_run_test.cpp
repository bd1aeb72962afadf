// Forked children: results come back in order whatever the number of jobs; a child's bad
// input stays bad input (exit code 2 for the CLI), any other failure is a runtime error.
#include <gtest/gtest.h>

#include <string>

#include "model/sc/fork_run.h"
#include "model/sc/stall_watchdog.h"
#include "traces/error.h"

namespace rtsim {
namespace {

TEST(ForkRun, ResultsComeBackInTheOrderGiven) {
  std::vector<std::function<std::string()>> work;
  for (int i = 0; i < 7; ++i)
    work.push_back([i] { return std::string(size_t(i) * 40000, char('a' + i)); });
  for (unsigned jobs : {1u, 3u}) {
    std::vector<std::string> out = run_in_children(work, jobs);
    ASSERT_EQ(out.size(), 7u);
    for (int i = 0; i < 7; ++i) EXPECT_EQ(out[i], std::string(size_t(i) * 40000, char('a' + i)));
  }
}

TEST(ForkRun, BadInputInAChildIsBadInputInTheParent) {
  try {
    run_in_child([]() -> std::string { throw InputError("x.rays: offset 12: truncated"); });
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "x.rays: offset 12: truncated");
  }
}

TEST(ForkRun, AStallInAChildIsAStallInTheParent) {  // exit 1 from validate, not 3
  try {
    run_in_child([]() -> std::string { throw SimStallError("no progress for 9 cycles"); });
    FAIL() << "no exception";
  } catch (const SimStallError& e) {
    EXPECT_STREQ(e.what(), "no progress for 9 cycles");
  }
}

TEST(ForkRun, OtherFailuresAreRuntimeErrors) {
  std::vector<std::function<std::string()>> work{
      [] { return std::string("fine"); },
      []() -> std::string { throw std::logic_error("broken invariant"); }};
  try {
    run_in_children(work, 2);
    FAIL() << "no exception";
  } catch (const InputError&) {
    FAIL() << "not bad input";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "broken invariant");
  }
}

}  // namespace
}  // namespace rtsim
