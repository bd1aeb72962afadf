// The static split: equal-area regions every frame; what a frame cost changes nothing.
#include "model/multi/impl/static_split.h"

namespace rtsim::multi {

StaticSplit::StaticSplit(uint32_t devices, uint32_t positions)
    : split_(equal_area_split(positions, devices)) {}

Split StaticSplit::next_split(const FramePreview&) const {
  return split_;
}

void StaticSplit::observe(const FrameFeedback&) {}

}  // namespace rtsim::multi
