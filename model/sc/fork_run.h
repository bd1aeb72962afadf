// SystemC allows one elaboration per process. To compare several simulations in one command
// (benchmarks, tests), each runs in a forked child: the parent has loaded the scene and built
// the BVH once, the child elaborates, simulates and returns its result as text.
#pragma once

#include <functional>
#include <string>

namespace rtsim {

// Runs fn in a child process and returns the text it returned. If fn throws, or the child
// dies, throws std::runtime_error with the child's message. The child must not use threads
// that the parent started (Embree's): build such things inside fn.
std::string run_in_child(const std::function<std::string()>& fn);

}  // namespace rtsim
