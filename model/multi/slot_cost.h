// What each ray cost the device, for the cost-weighted splits: the cycles it held a ray slot.
// In per-ray and packet modes an RT unit refills a warp only once all its rays have retired
// (model/sched/rt_core.cpp), so a warp's slots are held from its first dispatch to its last
// retirement, and that hold is shared by the warp's rays; in treelet mode a slot is refilled
// alone and a ray holds it for its own latency. A device's time is then close to the slot
// cycles of its rays over its slots, whatever the mix of short and long rays, which the sum
// of ray latencies is not. Built on RtSimulator's retire listener; plain C++.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "model/config/hw_config.h"
#include "model/sched/ray_supply.h"

namespace rtsim::multi {

class SlotCostListener : public RayRetireListener {
 public:
  // pixels: the image's pixel count; rays outside it are costed by type only.
  SlotCostListener(const HwConfig& config, uint32_t pixels);
  void retired(const RayContext& ray, Cycle now) override;
  // Closes the warps still open; call once after the run.
  void finish();

  const std::vector<double>& pixel_cost() const { return pixel_cost_; }  // by pixel index
  const std::array<double, kRayTypeCount>& type_rays() const { return type_rays_; }
  const std::array<double, kRayTypeCount>& type_cost() const { return type_cost_; }

 private:
  struct Warp {
    Cycle first_dispatch = 0, last_retire = 0;
    std::vector<std::pair<uint32_t, RayType>> rays;  // pixel and type of each ray in it
  };
  void close(Warp& warp);
  void charge(uint32_t pixel, RayType type, double cycles);

  bool per_warp_;
  uint32_t warps_per_unit_, warp_size_;
  std::vector<Warp> warps_;  // unit * warps_per_unit + warp
  std::vector<double> pixel_cost_;
  std::array<double, kRayTypeCount> type_rays_{}, type_cost_{};
};

}  // namespace rtsim::multi
