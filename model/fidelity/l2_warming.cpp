#include "model/fidelity/l2_warming.h"

#include <algorithm>

#include "model/mem/cache.h"
#include "model/sched/hardware_stack.h"

namespace rtsim {

L1Filter::L1Filter(const CacheConfig& config)
    : ways_(config.ways),
      sets_(uint32_t(config.size_bytes / (uint64_t(config.line_bytes) * config.ways))),
      line_shift_(uint32_t(__builtin_ctz(config.line_bytes))),
      sector_shift_(uint32_t(__builtin_ctz(block_bytes(config)))),
      lines_(size_t(sets_) * ways_) {}

L1Filter::Line& L1Filter::find(uint64_t line) {
  Line* set = &lines_[size_t(line % sets_) * ways_];
  uint32_t way = 0;
  while (way + 1 < ways_ && set[way].line != line) ++way;
  Line found = set[way].line == line ? set[way] : Line{line, 0};
  std::copy_backward(set, set + way, set + way + 1);
  set[0] = found;
  return set[0];
}

template <class Miss>
void L1Filter::read(uint64_t addr, uint32_t bytes, Miss miss) {
  uint64_t end = addr + std::max<uint32_t>(bytes, 1);
  for (uint64_t line = addr >> line_shift_; line <= (end - 1) >> line_shift_; ++line) {
    Line& l = find(line);
    uint64_t first = std::max(addr, line << line_shift_) >> sector_shift_;
    uint64_t last = (std::min(end, (line + 1) << line_shift_) - 1) >> sector_shift_;
    for (uint64_t sector = first; sector <= last; ++sector) {
      uint32_t bit = 1u << (sector & ((1u << (line_shift_ - sector_shift_)) - 1));
      if (l.sectors & bit) continue;
      l.sectors |= bit;
      miss(sector << sector_shift_, 1u << sector_shift_);
    }
  }
}

WarmingSource::WarmingSource(const std::vector<Ray>& rays, const std::vector<uint64_t>& warps,
                             uint64_t unit, RayRangeReader& reader, BvhView image,
                             const HwConfig& full, const HwConfig& scaled)
    : rays_(rays),
      warps_(warps),
      unit_(unit),
      reader_(reader),
      traversal_(image),
      stack_(full.rt.stack),
      warps_per_unit_(full.rt.warps),
      warp_size_(full.rt.warp_size),
      own_slots_(uint64_t(scaled.rt_units) * full.rt.warps * full.rt.warp_size),
      filter_(levels_as_built(full)[0].cache),
      absent_units_(full.rt_units - scaled.rt_units) {}

void WarmingSource::warm(RtSimulator& sim) {
  sim_ = &sim;
  l1s_.assign(absent_units_, L1Filter(filter_));
}

bool WarmingSource::next(Ray& ray) {
  if (position_ == rays_.size()) return false;
  if (sim_ && !l1s_.empty() && position_ % unit_ == 0) warm_until(warps_[position_ / unit_]);
  ray = rays_[position_++];
  return true;
}

void WarmingSource::warm_until(uint64_t warp) {
  for (; next_warp_ < warp; ++next_warp_) {
    others_.clear();
    reader_.read(next_warp_ * unit_, std::min((next_warp_ + 1) * unit_, reader_.rays()), others_);
    uint64_t absent = l1s_.size(), unit = next_warp_ % absent;
    uint64_t slot = (unit * warps_per_unit_ + next_warp_ / absent % warps_per_unit_) * warp_size_;
    for (size_t lane = 0; lane < others_.size(); ++lane) {
      auto context = uint32_t(own_slots_ + slot + lane);
      fetched_[int(others_[lane].type) % kRayTypeCount] +=
          trace(others_[lane], l1s_[unit], context);
    }
  }
  next_warp_ = warp + 1;
}

uint32_t WarmingSource::trace(const Ray& ray, L1Filter& l1, uint32_t context) {
  uint32_t fetched = 0, bytes = stack_.entry_bytes;
  auto to_l2 = [&](uint64_t addr, uint32_t n) { fetched += sim_->warm_l2(addr, n); };
  StackResidency stack;
  traversal_.begin(state_, ray);
  for (;;) {
    if (stack.refill(1) > 0)  // a step pops one entry
      sim_->warm_l2(HardwareStack::entry_address(context, stack.spilled, bytes), bytes);
    auto kept = uint32_t(std::max<size_t>(state_.stack.size(), 1) - 1);
    state_.accesses.clear();
    StepResult r = traversal_.step(state_);
    if (r.kind == StepKind::Done) return fetched;
    for (uint32_t a = r.first_access; a < r.first_access + r.access_count; ++a)
      l1.read(state_.accesses[a].address, state_.accesses[a].bytes, to_l2);
    if (uint32_t out = stack.settle(kept, uint32_t(state_.stack.size()), stack_.entries))
      sim_->warm_l2(HardwareStack::entry_address(context, stack.spilled - out, bytes), out * bytes,
                    true);
  }
}

}  // namespace rtsim
