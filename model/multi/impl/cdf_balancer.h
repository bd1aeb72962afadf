// The Harada & Fujita (2014) balancer: each device's speed from the previous frame,
// p_i = work / time; the ideal time t = N / sum(p_i); shares n_i = t * p_i; the split found
// on a CDF of per-pixel work. Work is the number of samples (the paper), the samples'
// simulated cost, or (CurrentCost) the rays of the frame about to be traced, each weighted by
// the previous frame's mean cost of its type times its pixel's factor: what the pixel's rays
// cost in the last frame that had any, over what their types' means predicted (1 if unknown).
// Degenerate input: a device that did no work or took no time keeps its last known speed
// (before any, the mean of the known speeds; with none known, all devices are equally fast);
// the first frame, which has no previous one, is split on the CDF of its own samples (the
// primary knows where they are once it has generated them) with every device equally fast;
// after a frame without work the split is by area and speed.
#pragma once

#include "model/multi/split_policy.h"

namespace rtsim::multi {

class CdfBalancer : public SplitPolicy {
 public:
  enum class Work { Samples, Cost, CurrentCost };
  CdfBalancer(Work work, uint32_t devices, uint32_t positions);
  using SplitPolicy::next_split;
  Split next_split(const FramePreview& next) const override;
  void observe(const FrameFeedback& frame) override;
  std::vector<double> speeds() const override;

 private:
  std::vector<double> predicted_cost(const FramePreview& next) const;

  Work work_;
  uint32_t devices_, positions_;
  std::vector<double> measured_;  // work per ns of each device's last useful frame; 0: none yet
  std::vector<double> weights_;   // the previous frame's work per position; empty before one
  std::array<double, kRayTypeCount> type_cost_{};  // CurrentCost: previous frame, per ray
  std::vector<double> pixel_factor_;               // CurrentCost: per position; 0: unknown
};

}  // namespace rtsim::multi
