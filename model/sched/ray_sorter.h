// Ray sorting unit between the dispatcher and the RT units, in the spirit of Intel's thread
// sorting unit and Vulkan-Sim's ray coherence engine: rays wait in a buffer of buffer_rays,
// binned by a coherence key, and a unit that asks for rays is given them bin by bin, fullest
// bin first, so the rays of a warp are likely to visit the same nodes.
// Keys (after Garanzha & Loop, "Fast ray sorting and breadth-first packet traversal for GPU
// ray tracing", Eurographics 2010): octant_cell = the direction's octant and the origin's cell
// in a grid^3 grid over the scene's bounds (8 * grid^3 bins); hash = the origin's cell and the
// unit direction quantised to direction_bins per axis, hashed into `bins` bins.
// Aging: a bin whose oldest ray has been overtaken by max_age buffers' worth of later rays
// (max_age * buffer_rays) is served first (0: never). Counted in rays, not cycles: in a full
// buffer every ray is overtaken by about buffer_rays rays whatever the clock.
// Timing: the sorter asks the dispatcher for rays whenever its buffer has room; the dispatcher's
// port and latency bring them (their `ready`: arrival). Only rays that have arrived are sorted:
// a take at `now` forms its group at the later of now and the arrival that gives the buffer
// enough rays for it, from the rays there by then; they leave `latency` cycles after that.
// Buffered rays hold ray contexts of their own (the pool grows by buffer_rays), so units never
// wait for the sorter beyond the rays' arrival while rays remain.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "model/sched/ray_supply.h"
#include "model/sched/treelet_policy.h"

namespace rtsim {

enum class SortKey : uint8_t { None, OctantCell, Hash };
const char* sort_key_name(SortKey key);  // none, octant_cell, hash

struct SortConfig {
  SortKey key = SortKey::None;
  uint32_t buffer_rays = 1024;  // rays: the sorting buffer
  uint32_t latency = 4;         // cycles: from the forming of a group to its reaching the unit
  uint32_t grid = 4;            // cells per axis of the origin grid over the scene's bounds
  uint32_t direction_bins = 4;  // hash: quantisation steps per direction component
  uint32_t bins = 256;          // hash: bins the key is hashed into
  uint32_t max_age = 4;         // buffers: overtaken by max_age * buffer_rays, served first
};

std::string sort_config_problem(const SortConfig& config);

// A buffered ray: the ray (origin, direction, tmin, tmax: 32 bytes) and its id and bin link (8).
constexpr uint32_t kSortedRayBytes = 40;
// The sorting buffer's SRAM (0 without a sorting unit).
inline double sort_buffer_bytes(const SortConfig& config) {
  return config.key == SortKey::None ? 0.0 : double(config.buffer_rays) * kSortedRayBytes;
}

struct SceneBounds {
  glm::vec3 lo{0.0f}, hi{0.0f};
};

// The bin of a ray under a key; octant bit i is set for a negative direction component i
// (-0.0 counts as negative, as its reciprocal does in the ray-box test).
class CoherenceKey {
 public:
  CoherenceKey(const SortConfig& config, const SceneBounds& bounds);
  uint32_t bins() const { return bins_; }
  uint32_t operator()(const Ray& ray) const;
  uint32_t origin_cell(const glm::vec3& origin) const;  // x + grid * (y + grid * z)
  static uint32_t octant(const glm::vec3& dir);

 private:
  SortConfig config_;
  SceneBounds bounds_;
  uint32_t bins_;
};

struct SortStats {
  uint64_t rays = 0;         // rays handed to the units
  uint64_t takes = 0;        // takes that received rays
  uint64_t bins_served = 0;  // bins the takes drew from, summed
  uint64_t aged = 0;         // bins served first because their oldest ray reached max_age
  uint64_t wait_cycles = 0;  // sum over rays of leaving - arrival
  uint64_t max_held = 0;     // most rays in the buffer or on their way, at once
};

class RaySorter : public RaySupply {
 public:
  // Throws std::invalid_argument for an impossible config (or key none).
  RaySorter(const SortConfig& config, const SceneBounds& bounds, RaySupply& upstream);

  size_t take(uint32_t unit, Cycle now, size_t max, std::vector<RayContext*>& out) override;
  void retire(RayContext& ray, Cycle now) override { upstream_.retire(ray, now); }
  bool exhausted() const override { return held_ == 0 && upstream_.exhausted(); }

  const SortStats& stats() const { return stats_; }
  uint32_t held() const { return held_; }  // in the buffer or on their way to it
  const CoherenceKey& key() const { return key_; }
  // Called with every ray as it leaves, `handed` set (the simulator marks warm-up and frames).
  void watch(std::function<void(const RayContext&)> watcher) { watcher_ = std::move(watcher); }

 private:
  void fill(uint32_t unit, Cycle now);
  // Bins the rays that have arrived by `at`, in arrival order.
  void admit(Cycle at);
  size_t serve(uint32_t bin, Cycle at, size_t max, std::vector<RayContext*>& out);
  void set_length(uint32_t bin, uint32_t length);

  SortConfig config_;
  CoherenceKey key_;
  RaySupply& upstream_;
  std::unique_ptr<TreeletPolicy> fullest_;  // the treelet queues' "fullest" policy, over bins
  std::vector<RayFifo> bins_;
  std::set<std::pair<uint64_t, uint32_t>> by_head_;  // (sequence of a bin's oldest ray, bin)
  std::vector<RayContext*> arrivals_;
  RayFifo on_the_way_;  // dispatched to the sorter, not binned yet, in arrival order
  uint32_t held_ = 0, binned_ = 0;
  uint64_t newest_ = 0;  // sequence of the latest ray binned
  std::function<void(const RayContext&)> watcher_;
  SortStats stats_;
};

}  // namespace rtsim
