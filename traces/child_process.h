// What every child process rtsim forks does first: end when its parent does. Without it a
// `kill -9` of a sweep leaves its `rtsim run` children running as orphans that write results
// later. SIGTERM lets the child remove its temporaries (traces/output_file.h) on the way out.
#pragma once

#include <signal.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <cstdio>

namespace rtsim {

// fork(), after flushing stdio (no buffered output is written twice); the child ends when
// this process does. Returns what fork() returns.
inline pid_t fork_child() {
  std::fflush(nullptr);
  pid_t parent = ::getpid();
  pid_t pid = ::fork();
  if (pid == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != parent) ::_exit(1);  // the parent died before the request took effect
  }
  return pid;
}

}  // namespace rtsim
