// SystemC allows one elaboration per process. To compare several simulations in one command
// (benchmarks, tests, the devices of a multi-device frame), each runs in a forked child: the
// parent has loaded the scene and built the BVH once, the children share them copy-on-write,
// elaborate, simulate and return their result as text.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace rtsim {

// Runs the functions in child processes, up to `jobs` at a time, in the order given, and
// returns each one's text in that order. If one throws or its child dies, starts no more,
// waits for the running children and throws that child's message: as InputError if the child
// threw InputError (bad input stays exit code 2), as SimStallError if it threw that (a stall
// stays exit code 1), else as std::runtime_error. The children
// must not use threads that the parent started (Embree's): build such things inside fn.
std::vector<std::string> run_in_children(const std::vector<std::function<std::string()>>& work,
                                         unsigned jobs);

// One function in one child.
std::string run_in_child(const std::function<std::string()>& fn);

}  // namespace rtsim
