// What every child process rtsim forks does first: end when its parent does. Without it a
// `kill -9` of a sweep leaves its `rtsim run` children running as orphans that write results
// later. SIGTERM lets the child remove its temporaries (traces/output_file.h) on the way out.
#pragma once

#include <signal.h>
#include <sys/prctl.h>
#include <unistd.h>

namespace rtsim {

// Called in the child right after fork(); parent is the pid the parent had before it.
inline void end_with_parent(pid_t parent) {
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (::getppid() != parent) ::_exit(1);  // the parent died before the request took effect
}

}  // namespace rtsim
