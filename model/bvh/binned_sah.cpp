#include "model/bvh/binned_sah.h"

#include <algorithm>
#include <array>

namespace rtsim {
namespace {

struct PrimRef {
  Bounds box;
  glm::vec3 centroid;
  uint32_t id;
};

struct Split {
  int axis = -1;
  int bin = 0;  // references in bins [0, bin] go left
  float cost = 0.0f;
};

struct Binner {
  int bins;
  Bounds centroids;
  glm::vec3 scale;  // bins per unit of centroid extent, 0 on a flat axis

  int bin_of(const PrimRef& ref, int axis) const {
    int b = static_cast<int>((ref.centroid[axis] - centroids.lo[axis]) * scale[axis]);
    return std::clamp(b, 0, bins - 1);
  }
};

// Cheapest bin boundary over the three axes; axis -1 if every centroid coincides.
Split best_split(const std::vector<PrimRef>& refs, uint32_t begin, uint32_t end,
                 const Binner& binner, float node_cost, float parent_area) {
  Split best;
  for (int axis = 0; axis < 3; ++axis) {
    if (binner.scale[axis] <= 0.0f) continue;
    std::array<Bounds, 32> box{};
    std::array<uint32_t, 32> count{};
    // Drop each reference into its bin.
    for (uint32_t i = begin; i < end; ++i) {
      int b = binner.bin_of(refs[i], axis);
      box[b].grow(refs[i].box);
      count[b]++;
    }
    // Sweep from the right to get the area and count right of each boundary.
    std::array<float, 32> right_cost{};
    Bounds right;
    uint32_t right_count = 0;
    for (int b = binner.bins - 1; b > 0; --b) {
      right.grow(box[b]);
      right_count += count[b];
      right_cost[b] = right.surface_area() * right_count;
    }
    // Sweep from the left and keep the cheapest boundary.
    Bounds left;
    uint32_t left_count = 0;
    for (int b = 0; b < binner.bins - 1; ++b) {
      left.grow(box[b]);
      left_count += count[b];
      if (left_count == 0 || left_count == end - begin) continue;
      float cost = node_cost + (left.surface_area() * left_count + right_cost[b + 1]) /
                                   std::max(parent_area, 1e-30f);
      if (best.axis < 0 || cost < best.cost) best = {axis, b, cost};
    }
  }
  return best;
}

Bvh2 build_over(std::vector<PrimRef> refs, const BvhConfig& config) {
  Bvh2 bvh;
  auto n = static_cast<uint32_t>(refs.size());
  bvh.nodes.reserve(2 * size_t(n) + 1);
  bvh.nodes.emplace_back();
  struct Task {
    uint32_t node, begin, end, depth;
  };
  std::vector<Task> tasks{{0, 0, n, 0}};
  while (!tasks.empty()) {
    Task task = tasks.back();
    tasks.pop_back();
    uint32_t count = task.end - task.begin;
    // Bound the references and their centroids.
    Bounds box;
    Binner binner{config.sah_bins, {}, {}};
    for (uint32_t i = task.begin; i < task.end; ++i) {
      box.grow(refs[i].box);
      binner.centroids.grow(refs[i].centroid);
    }
    bvh.nodes[task.node].box = box;
    bvh.depth = std::max(bvh.depth, task.depth);
    glm::vec3 extent = binner.centroids.extent();
    for (int a = 0; a < 3; ++a)
      binner.scale[a] = extent[a] > 0.0f ? config.sah_bins / extent[a] : 0.0f;
    // Split where the SAH is cheapest; stay a leaf if that is cheaper and allowed.
    Split split = count > 1 ? best_split(refs, task.begin, task.end, binner, config.sah_node_cost,
                                         box.surface_area())
                            : Split{};
    bool fits = count <= static_cast<uint32_t>(config.max_leaf_size);
    if (fits && (split.axis < 0 || split.cost >= static_cast<float>(count))) {
      bvh.nodes[task.node].first = task.begin;
      bvh.nodes[task.node].count = count;
      continue;
    }
    uint32_t mid;
    if (split.axis >= 0) {
      auto goes_left = [&](const PrimRef& r) { return binner.bin_of(r, split.axis) <= split.bin; };
      mid = static_cast<uint32_t>(
          std::partition(refs.begin() + task.begin, refs.begin() + task.end, goes_left) -
          refs.begin());
    } else {
      // Every centroid coincides: halve the range by index.
      mid = task.begin + count / 2;
    }
    uint32_t left = static_cast<uint32_t>(bvh.nodes.size());
    bvh.nodes.emplace_back();
    bvh.nodes.emplace_back();
    bvh.nodes[task.node].first = left;
    tasks.push_back({left + 1, mid, task.end, task.depth + 1});
    tasks.push_back({left, task.begin, mid, task.depth + 1});
  }
  bvh.prim_order.resize(n);
  for (uint32_t i = 0; i < n; ++i) bvh.prim_order[i] = refs[i].id;
  return bvh;
}

}  // namespace

Bvh2 build_binned_sah(const TriangleMesh& mesh, const BvhConfig& config) {
  std::vector<PrimRef> refs(mesh.triangle_count());
  for (uint32_t i = 0; i < refs.size(); ++i) {
    Bounds b;
    for (int c = 0; c < 3; ++c) b.grow(mesh.vertex(i, c));
    refs[i] = {b, b.center(), i};
  }
  return build_over(std::move(refs), config);
}

Bvh2 build_binned_sah(const std::vector<Bounds>& boxes, const BvhConfig& config) {
  std::vector<PrimRef> refs(boxes.size());
  for (uint32_t i = 0; i < refs.size(); ++i) refs[i] = {boxes[i], boxes[i].center(), i};
  return build_over(std::move(refs), config);
}

}  // namespace rtsim
