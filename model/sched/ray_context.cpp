#include "model/sched/ray_context.h"

namespace rtsim {

RayContextPool::RayContextPool(uint32_t capacity) {
  contexts_.reserve(capacity);
  free_.reserve(capacity);
  for (uint32_t i = 0; i < capacity; ++i) {
    contexts_.push_back(std::make_unique<RayContext>());
    contexts_.back()->id = i;
  }
  for (uint32_t i = capacity; i-- > 0;) free_.push_back(contexts_[i].get());
}

RayContext* RayContextPool::acquire() {
  if (free_.empty()) return nullptr;
  RayContext* context = free_.back();
  free_.pop_back();
  return context;
}

void RayContextPool::release(RayContext* context) {
  free_.push_back(context);
}

}  // namespace rtsim
