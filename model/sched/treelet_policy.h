// Which treelet queue an RT unit serves next, behind one interface; implementations in impl/.
// A policy sees only queue lengths as they change; it may change only its own state.
// Aila & Karras (HPG 2010) find that the scheduling policy matters: serving the fullest queue
// amortizes a treelet's fetch over the most rays; serving the oldest bounds ray latency.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rtsim {

class TreeletPolicy {
 public:
  virtual ~TreeletPolicy() = default;
  // The queue of `treelet` went from `before` to `after` rays.
  virtual void changed(uint32_t treelet, uint32_t before, uint32_t after) = 0;
  // The treelet to serve next; nullopt when every queue is empty.
  virtual std::optional<uint32_t> pick() const = 0;
};

// "fullest" or "oldest"; nullptr for an unknown name.
std::unique_ptr<TreeletPolicy> make_treelet_policy(const std::string& name, uint32_t treelets);
std::vector<std::string> treelet_policy_names();

}  // namespace rtsim
