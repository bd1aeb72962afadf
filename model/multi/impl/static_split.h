// The static equal-area split (the baseline of Harada & Fujita 2014).
#pragma once

#include "model/multi/split_policy.h"

namespace rtsim::multi {

class StaticSplit : public SplitPolicy {
 public:
  StaticSplit(uint32_t devices, uint32_t positions);
  using SplitPolicy::next_split;
  Split next_split(const FramePreview& next) const override;
  void observe(const FrameFeedback& frame) override;

 private:
  Split split_;
};

}  // namespace rtsim::multi
