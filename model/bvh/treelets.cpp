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

// Node and leaf-triangle bytes of a unit.
struct UnitBytes {
  uint64_t nodes = 0, triangles = 0;
  uint64_t budgeted(const TreeletRule& rule) const {
    return nodes + (rule.budget == TreeletBudget::NodesAndTriangles ? triangles : 0);
  }
  UnitBytes& operator+=(const UnitBytes& o) {
    nodes += o.nodes;
    triangles += o.triangles;
    return *this;
  }
};

UnitBytes unit_bytes(const WideBvh& bvh, const Unit& unit, const TreeletRule& rule) {
  UnitBytes b;
  for (uint32_t n : unit) {
    b.nodes += rule.node_bytes;
    for (int c = 0; c < bvh.nodes[n].child_count; ++c)
      b.triangles += uint64_t(bvh.nodes[n].child[c].count) * rule.triangle_bytes;
  }
  return b;
}

TreeletStats summarize(const std::vector<UnitBytes>& treelets, const TreeletRule& rule) {
  TreeletStats s;
  s.count = static_cast<uint32_t>(treelets.size());
  s.budget_bytes = rule.budget_bytes;
  s.budget = rule.budget;
  s.min_bytes = treelets.empty() ? 0 : treelets[0].budgeted(rule);
  for (const UnitBytes& t : treelets) {
    uint64_t bytes = t.budgeted(rule);
    s.oversized += bytes > rule.budget_bytes;
    s.min_bytes = std::min(s.min_bytes, bytes);
    s.max_bytes = std::max(s.max_bytes, bytes);
    s.total_bytes += bytes;
    uint64_t bin = bytes == 0 ? 0 : (bytes * 10 - 1) / rule.budget_bytes;
    s.fill_histogram[std::min<uint64_t>(bin, 9)]++;
    s.node_bytes += t.nodes;
    s.triangle_bytes += t.triangles;
    s.max_triangle_bytes = std::max(s.max_triangle_bytes, t.triangles);
  }
  return s;
}

}  // namespace

Treelets form_treelets(WideBvh& bvh, const TreeletRule& rule) {
  Treelets out;
  std::vector<UnitBytes> sizes;
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
    UnitBytes bytes;
    std::priority_queue<Candidate> frontier;
    frontier.push(candidate(std::move(roots.front())));
    roots.pop_front();
    while (!frontier.empty()) {
      Candidate best = frontier.top();
      frontier.pop();
      UnitBytes add = unit_bytes(bvh, best.unit, rule);
      uint64_t budgeted = bytes.budgeted(rule);
      // A unit that no longer fits roots a later treelet.
      if (budgeted > 0 && budgeted + add.budgeted(rule) > rule.budget_bytes) {
        roots.push_back(std::move(best.unit));
        continue;
      }
      // Take the unit and offer its children.
      for (uint32_t n : best.unit) {
        bvh.nodes[n].treelet = id;
        out.nodes[id].push_back(n);
      }
      bytes += add;
      for (Unit& child : child_units(bvh, best.unit, rule.sibling_groups))
        frontier.push(candidate(std::move(child)));
    }
    sizes.push_back(bytes);
  }
  out.stats = summarize(sizes, rule);
  return out;
}

}  // namespace rtsim
