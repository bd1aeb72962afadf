#include "model/sched/treelet_prefetcher.h"

#include <algorithm>

#include "model/bvh/node_format.h"

namespace rtsim {
namespace {

// Appends [addr, addr + bytes), extending the last range if it ends where this one starts.
void add_range(std::vector<ByteRange>& ranges, uint64_t addr, uint32_t bytes) {
  if (!ranges.empty() && ranges.back().addr + ranges.back().bytes == addr)
    ranges.back().bytes += bytes;
  else
    ranges.push_back({addr, bytes});
}

}  // namespace

const char* prefetch_trigger_name(PrefetchTrigger trigger) {
  switch (trigger) {
    case PrefetchTrigger::FirstVisit: return "first_visit";
    case PrefetchTrigger::Batch: return "batch";
    default: return "none";
  }
}

TreeletFootprints treelet_footprints(BvhView bvh) {
  uint32_t count = bvh.treelet_count();
  std::vector<std::vector<ByteRange>> nodes(count), triangles(count);
  NodeView view;
  for (const BvhImage* level : bvh.levels()) {
    const BvhImage& image = *level;
    for (uint32_t position = 0; position < image.positions(); ++position) {
      if (!image.holds_node(position)) continue;  // xe6: a leaf block
      uint32_t t = node_treelet(image, position);
      add_range(nodes[t], image.node_address(position), image.node_size);
      decode_node(image.config.node_format, image.config.width, image.node_bytes(position), view,
                  position, image.regions());
      for (int s = 0; s < view.slots; ++s)
        if ((view.valid >> s & 1) && view.count[s] > 0)
          add_range(triangles[t], image.triangle_address(view.index[s]),
                    view.count[s] * image.triangle_stride);
    }
  }
  for (uint32_t t = 0; t < count; ++t)
    nodes[t].insert(nodes[t].end(), triangles[t].begin(), triangles[t].end());
  return nodes;
}

TreeletPrefetcher::TreeletPrefetcher(const PrefetchConfig& config,
                                     const TreeletFootprints* footprints)
    : config_(config), footprints_(footprints) {
  if (config.trigger == PrefetchTrigger::FirstVisit) recent_.assign(config.recent, ~0u);
}

const std::vector<ByteRange>& TreeletPrefetcher::on_node(uint32_t treelet) {
  if (config_.trigger != PrefetchTrigger::FirstVisit) return none_;
  if (std::find(recent_.begin(), recent_.end(), treelet) != recent_.end()) {
    stats_.skipped++;
    return none_;
  }
  recent_[next_] = treelet;
  next_ = (next_ + 1) % uint32_t(recent_.size());
  return start(treelet);
}

const std::vector<ByteRange>& TreeletPrefetcher::on_batch(uint32_t treelet, uint32_t rays) {
  if (config_.trigger != PrefetchTrigger::Batch || rays < config_.batch_rays) return none_;
  return start(treelet);
}

const std::vector<ByteRange>& TreeletPrefetcher::start(uint32_t treelet) {
  ranges_.clear();
  uint64_t left = config_.max_bytes ? config_.max_bytes : ~uint64_t(0);
  for (const ByteRange& r : (*footprints_)[treelet]) {
    if (left == 0) break;
    auto bytes = uint32_t(std::min<uint64_t>(r.bytes, left));
    ranges_.push_back({r.addr, bytes});
    left -= bytes;
    stats_.bytes += bytes;
  }
  stats_.treelets++;
  return ranges_;
}

}  // namespace rtsim
