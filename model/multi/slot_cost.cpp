#include "model/multi/slot_cost.h"

#include <algorithm>

#include "model/sched/ray_context.h"

namespace rtsim::multi {

SlotCostListener::SlotCostListener(const HwConfig& config, uint32_t pixels)
    : per_warp_(config.rt.mode != TraversalMode::Treelet),
      warps_per_unit_(config.rt.warps),
      warp_size_(config.rt.warp_size),
      warps_(size_t(config.rt_units) * config.rt.warps),
      pixel_cost_(pixels, 0.0) {}

void SlotCostListener::charge(uint32_t pixel, RayType type, double cycles) {
  if (pixel < pixel_cost_.size()) pixel_cost_[pixel] += cycles;
  type_rays_[size_t(type)] += 1;
  type_cost_[size_t(type)] += cycles;
}

void SlotCostListener::close(Warp& warp) {
  if (warp.rays.empty()) return;
  double share = double(warp.last_retire - warp.first_dispatch) / double(warp.rays.size());
  for (auto [pixel, type] : warp.rays) charge(pixel, type, share);
  warp.rays.clear();
}

void SlotCostListener::retired(const RayContext& ray, Cycle now) {
  if (!per_warp_) {
    charge(ray.ray.pixel, ray.ray.type, double(now - std::min(now, ray.dispatched)));
    return;
  }
  Warp& warp = warps_.at(size_t(ray.unit) * warps_per_unit_ + ray.slot / warp_size_);
  // A warp is refilled only after its last ray retired: a ray handed to it at or after that
  // retirement belongs to the next fill (handed: after the sorting unit, if there is one).
  if (!warp.rays.empty() && ray.handed >= warp.last_retire) close(warp);
  if (warp.rays.empty()) warp.first_dispatch = warp.last_retire = ray.handed;
  warp.first_dispatch = std::min(warp.first_dispatch, ray.handed);
  warp.last_retire = std::max(warp.last_retire, now);
  warp.rays.emplace_back(ray.ray.pixel, ray.ray.type);
}

void SlotCostListener::finish() {
  for (Warp& warp : warps_) close(warp);
}

}  // namespace rtsim::multi
