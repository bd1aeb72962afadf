// Host clocks for the commands that time themselves, in seconds: the CPU time of this process
// (with one thread, its time on one core whatever else a shared, busy machine runs) and
// monotonic wall time.
#pragma once

#include <ctime>

namespace rtsim {

inline double clock_seconds(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

inline double cpu_seconds() {
  return clock_seconds(CLOCK_PROCESS_CPUTIME_ID);
}
inline double wall_seconds() {
  return clock_seconds(CLOCK_MONOTONIC);
}

}  // namespace rtsim
