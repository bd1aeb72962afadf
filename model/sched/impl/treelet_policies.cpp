// The treelet scheduling policies:
//  - fullest: the queue holding the most rays (ties: the lower treelet id), so each treelet
//    fetch serves as many rays as possible;
//  - oldest: the queue that became non-empty first, so no queue starves.
#include <set>
#include <utility>

#include "model/sched/treelet_policy.h"

namespace rtsim {
namespace {

class FullestPolicy : public TreeletPolicy {
 public:
  void changed(uint32_t treelet, uint32_t before, uint32_t after) override {
    if (before > 0) by_length_.erase({before, treelet});
    if (after > 0) by_length_.insert({after, treelet});
  }
  std::optional<uint32_t> pick() const override {
    if (by_length_.empty()) return std::nullopt;
    return by_length_.begin()->second;
  }

 private:
  struct Longer {
    bool operator()(const std::pair<uint32_t, uint32_t>& a,
                    const std::pair<uint32_t, uint32_t>& b) const {
      return a.first != b.first ? a.first > b.first : a.second < b.second;
    }
  };
  std::set<std::pair<uint32_t, uint32_t>, Longer> by_length_;  // (rays, treelet)
};

class OldestPolicy : public TreeletPolicy {
 public:
  explicit OldestPolicy(uint32_t treelets) : since_(treelets, 0) {}
  void changed(uint32_t treelet, uint32_t before, uint32_t after) override {
    if (before == 0 && after > 0) {
      since_[treelet] = next_++;
      by_age_.insert({since_[treelet], treelet});
    } else if (before > 0 && after == 0) {
      by_age_.erase({since_[treelet], treelet});
    }
  }
  std::optional<uint32_t> pick() const override {
    if (by_age_.empty()) return std::nullopt;
    return by_age_.begin()->second;
  }

 private:
  std::vector<uint64_t> since_;  // when each non-empty queue last became non-empty
  std::set<std::pair<uint64_t, uint32_t>> by_age_;
  uint64_t next_ = 0;
};

}  // namespace

std::unique_ptr<TreeletPolicy> make_treelet_policy(const std::string& name, uint32_t treelets) {
  if (name == "fullest") return std::make_unique<FullestPolicy>();
  if (name == "oldest") return std::make_unique<OldestPolicy>(treelets);
  return nullptr;
}

std::vector<std::string> treelet_policy_names() {
  return {"fullest", "oldest"};
}

}  // namespace rtsim
