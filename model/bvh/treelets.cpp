#include "model/bvh/treelets.h"

#include <algorithm>
#include <deque>
#include <queue>

namespace rtsim {
namespace {

// A unit: nodes that join a treelet together (one node, or one sibling group).
using Unit = std::vector<uint32_t>;

std::vector<Unit> child_units(const WideBvh& bvh, const Unit& unit, bool sibling_groups) {
  std::vector<Unit> units;
  for (uint32_t n : unit) {
    Unit group;
    for (int c = 0; c < bvh.nodes[n].child_count; ++c) {
      const WideChild& child = bvh.nodes[n].child[c];
      if (child.leaf()) continue;
      if (sibling_groups)
        group.push_back(child.node);
      else
        units.push_back({child.node});
    }
    if (!group.empty()) units.push_back(group);
  }
  return units;
}

TreeletStats summarize(const std::vector<uint64_t>& sizes, uint32_t budget) {
  TreeletStats s;
  s.count = static_cast<uint32_t>(sizes.size());
  s.budget_bytes = budget;
  s.min_bytes = sizes.empty() ? 0 : sizes[0];
  for (uint64_t bytes : sizes) {
    s.oversized += bytes > budget;
    s.min_bytes = std::min(s.min_bytes, bytes);
    s.max_bytes = std::max(s.max_bytes, bytes);
    s.total_bytes += bytes;
    uint64_t bin = bytes == 0 ? 0 : (bytes * 10 - 1) / budget;
    s.fill_histogram[std::min<uint64_t>(bin, 9)]++;
  }
  return s;
}

}  // namespace

Treelets form_treelets(WideBvh& bvh, uint32_t node_bytes, bool sibling_groups,
                       uint32_t budget_bytes) {
  Treelets out;
  std::vector<uint64_t> sizes;
  std::deque<Unit> roots{{0}};
  // Candidates by surface area, ties broken by arrival so the result is deterministic.
  struct Candidate {
    float area;
    uint64_t seq;
    Unit unit;
    bool operator<(const Candidate& o) const {
      return area < o.area || (area == o.area && seq > o.seq);
    }
  };
  uint64_t seq = 0;
  auto candidate = [&](Unit unit) {
    float area = 0.0f;
    for (uint32_t n : unit) area += bvh.nodes[n].box.surface_area();
    return Candidate{area, seq++, std::move(unit)};
  };
  while (!roots.empty()) {
    uint32_t id = static_cast<uint32_t>(out.nodes.size());
    out.nodes.emplace_back();
    uint64_t bytes = 0;
    std::priority_queue<Candidate> frontier;
    frontier.push(candidate(std::move(roots.front())));
    roots.pop_front();
    while (!frontier.empty()) {
      Candidate best = frontier.top();
      frontier.pop();
      uint64_t unit_bytes = uint64_t(node_bytes) * best.unit.size();
      // A unit that no longer fits roots a later treelet.
      if (bytes > 0 && bytes + unit_bytes > budget_bytes) {
        roots.push_back(std::move(best.unit));
        continue;
      }
      // Take the unit and offer its children.
      for (uint32_t n : best.unit) {
        bvh.nodes[n].treelet = id;
        out.nodes[id].push_back(n);
      }
      bytes += unit_bytes;
      for (Unit& child : child_units(bvh, best.unit, sibling_groups))
        frontier.push(candidate(std::move(child)));
    }
    sizes.push_back(bytes);
  }
  out.stats = summarize(sizes, budget_bytes);
  return out;
}

}  // namespace rtsim
