// The local core count that sweeps and suites run points by: the CPUs this process may run on
// (a taskset or cpuset), not every CPU of the machine.
#include <gtest/gtest.h>

#include <sched.h>

#include "reports/process_pool.h"

namespace rtsim {
namespace {

TEST(ProcessPool, LocalCoresAreTheCpusThisProcessMayRunOn) {
  cpu_set_t all;
  ASSERT_EQ(sched_getaffinity(0, sizeof all, &all), 0);
  EXPECT_EQ(reports::local_cores(), uint32_t(CPU_COUNT(&all)));
  int first = 0;
  while (!CPU_ISSET(first, &all)) ++first;
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(first, &one);
  ASSERT_EQ(sched_setaffinity(0, sizeof one, &one), 0);
  EXPECT_EQ(reports::local_cores(), 1u) << "a sweep under `taskset -c 0` runs one point at a time";
  ASSERT_EQ(sched_setaffinity(0, sizeof all, &all), 0);
}

}  // namespace
}  // namespace rtsim
