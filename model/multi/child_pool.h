// Runs functions in forked child processes, up to `jobs` at a time. SystemC allows one
// elaboration per process, so every simulated device of every frame runs in a child of its
// own (as model/sc/fork_run.h does one at a time); the parent has built the BVH and read the
// rays once, and the children share them copy-on-write.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace rtsim::multi {

// Returns each function's text, in the order given; functions start in that order. If one
// throws or its child dies, starts no more, waits for the running children and throws
// std::runtime_error with that child's message.
std::vector<std::string> run_in_children(const std::vector<std::function<std::string()>>& work,
                                         unsigned jobs);

}  // namespace rtsim::multi
