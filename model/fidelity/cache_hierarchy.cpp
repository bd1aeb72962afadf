#include "model/fidelity/cache_hierarchy.h"

#include <algorithm>

#include "model/mem/slice_hash.h"

namespace rtsim {

std::vector<std::string> level_names(const std::vector<MemoryLevelConfig>& levels) {
  std::vector<std::string> names;
  for (const MemoryLevelConfig& level : levels) names.push_back(level.name);
  return names;
}

// One instance of a level: its slices, and the sink when its level is the tapped one.
class CacheHierarchy::Instance : public MemoryTarget {
 public:
  Instance(const std::vector<MemoryLevelConfig>& levels, uint32_t level, uint32_t index,
           MemoryTarget& below, LevelReferenceSink* sink)
      : index_(index),
        line_shift_(uint32_t(__builtin_ctz(levels[level].cache.line_bytes))),
        block_bytes_(block_bytes(levels[level].cache)),
        sink_(sink) {
    CacheConfig slice = levels[level].cache;
    slice.size_bytes /= levels[level].slices;
    for (uint32_t s = 0; s < levels[level].slices; ++s)
      slices_.push_back(std::make_unique<Cache>(slice, &below, cache_place(levels, level)));
  }

  Cycle read(uint64_t addr, uint32_t bytes, Cycle at, ReadClient* client, uint64_t token,
             ReadCharge& charge) override {
    tell(addr, bytes, LevelReference::Read);
    return slice(addr).read(addr, bytes, at, client, token, charge);
  }
  void write(uint64_t addr, uint32_t bytes, Cycle at) override {
    tell(addr, bytes, LevelReference::Write);
    slice(addr).write(addr, bytes, at);
  }
  void fill(uint64_t addr, uint32_t bytes, Cycle at) override {
    tell(addr, bytes, LevelReference::Fill);
    slice(addr).fill(addr, bytes, at);
  }
  CacheStats stats() const {
    CacheStats sum;
    for (const auto& s : slices_) sum += s->stats();
    return sum;
  }

 private:
  // A request to a sliced instance comes from the level above, a block or a line at a time;
  // the first level, whose requests may span lines, has one slice.
  Cache& slice(uint64_t addr) {
    return *slices_[slice_of_line(addr >> line_shift_, uint32_t(slices_.size()))];
  }
  void tell(uint64_t addr, uint32_t bytes, LevelReference kind) {
    if (!sink_) return;
    uint64_t end = addr + std::max<uint32_t>(bytes, 1);
    for (uint64_t b = addr / block_bytes_; b <= (end - 1) / block_bytes_; ++b)
      sink_->reference(index_, b * block_bytes_, kind);
  }

  uint32_t index_, line_shift_, block_bytes_;
  LevelReferenceSink* sink_;
  std::vector<std::unique_ptr<Cache>> slices_;
};

CacheHierarchy::CacheHierarchy(const std::vector<MemoryLevelConfig>& levels, uint32_t units,
                               MemoryTarget& dram, LevelReferenceSink* sink, uint32_t tapped)
    : levels_(levels), instances_(levels.size()) {
  for (uint32_t i = uint32_t(levels.size()); i-- > 0;) {
    uint32_t per = units_per_instance(levels[i], units);
    for (uint32_t k = 0; k < level_instances(levels[i], units); ++k) {
      MemoryTarget* below = &dram;
      if (i + 1 < levels.size())
        below = instances_[i + 1][k * per / units_per_instance(levels[i + 1], units)].get();
      instances_[i].push_back(
          std::make_unique<Instance>(levels, i, k, *below, i == tapped ? sink : nullptr));
    }
  }
}

CacheHierarchy::~CacheHierarchy() = default;

MemoryTarget& CacheHierarchy::unit(uint32_t unit) {
  return *instances_[0][unit];
}

uint32_t CacheHierarchy::instances(uint32_t level) const {
  return uint32_t(instances_[level].size());
}

CacheStats CacheHierarchy::stats(uint32_t level) const {
  CacheStats sum;
  for (const auto& inst : instances_[level]) sum += inst->stats();
  return sum;
}

}  // namespace rtsim
