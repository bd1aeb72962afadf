// Treelet prefetching (Chou et al., "Treelet Prefetching For Ray Tracing", MICRO 2023): an RT
// unit fetches a whole treelet into its L1 ahead of the rays that will walk it, instead of one
// node per step. A treelet's footprint is its nodes and the triangles of their leaves, as byte
// ranges of the BVH image (contiguous runs merged; with the treelet layout a treelet is one run
// of nodes and one of triangles). Triggers:
//  - first_visit (depth-first and treelet modes): a node step into a treelet the unit has not
//    prefetched among its last `recent` treelets;
//  - batch (treelet mode): the unit takes a batch of at least `batch_rays` rays from one
//    treelet's queue (the batch, capped by the unit's free slots, standing in for Chou et al.'s
//    per-treelet count of waiting rays).
// The L1 treats the prefetch as misses nobody waits for (model/mem/cache.h): accuracy (useful /
// prefetched blocks) and coverage (useful / (useful + demand misses)) come from its counters.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/bvh/two_level.h"

namespace rtsim {

enum class PrefetchTrigger : uint8_t { None, FirstVisit, Batch };
const char* prefetch_trigger_name(PrefetchTrigger trigger);  // none, first_visit, batch

struct PrefetchConfig {
  PrefetchTrigger trigger = PrefetchTrigger::None;
  uint32_t batch_rays = 32;  // rays: batch trigger, the smallest batch that prefetches
  uint32_t recent = 8;       // treelets: first_visit trigger, the unit's memory of its prefetches
  uint32_t max_bytes = 0;    // bytes: most bytes of a treelet one prefetch fetches; 0 = all
};

struct ByteRange {
  uint64_t addr = 0;
  uint32_t bytes = 0;
};

// Per treelet: the byte ranges of its nodes, then of its leaves' triangles. Computed once per
// simulation and shared by the units.
using TreeletFootprints = std::vector<std::vector<ByteRange>>;
TreeletFootprints treelet_footprints(BvhView bvh);

struct PrefetchStats {
  uint64_t treelets = 0;  // prefetches started
  uint64_t bytes = 0;     // bytes they asked for (present blocks included)
  uint64_t skipped = 0;   // first_visit: node steps into a treelet prefetched recently
};

// One RT unit's prefetcher: decides when, and which bytes to send to its L1.
class TreeletPrefetcher {
 public:
  // footprints: from treelet_footprints; may be null when trigger is None.
  TreeletPrefetcher(const PrefetchConfig& config, const TreeletFootprints* footprints);
  const PrefetchConfig& config() const { return config_; }
  // first_visit: a node step into `treelet`; batch: a batch of `rays` rays of `treelet`. Return
  // the ranges to prefetch now (empty: none), valid until the next call.
  const std::vector<ByteRange>& on_node(uint32_t treelet);
  const std::vector<ByteRange>& on_batch(uint32_t treelet, uint32_t rays);
  const PrefetchStats& stats() const { return stats_; }

 private:
  const std::vector<ByteRange>& start(uint32_t treelet);

  PrefetchConfig config_;
  const TreeletFootprints* footprints_;
  std::vector<uint32_t> recent_;  // ring of the last treelets prefetched
  uint32_t next_ = 0;
  std::vector<ByteRange> ranges_, none_;
  PrefetchStats stats_;
};

}  // namespace rtsim
