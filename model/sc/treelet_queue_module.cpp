#include "model/sc/treelet_queue_module.h"

#include <sstream>

namespace rtsim {

// Forwards to the scheduler and wakes sleeping units when rays may have become available.
class TreeletQueueModule::Notifying : public RaySupply {
 public:
  Notifying(TreeletScheduler& scheduler, sc_core::sc_event& work)
      : scheduler_(scheduler), work_(work) {}
  size_t take(uint32_t unit, Cycle now, size_t max, std::vector<RayContext*>& out) override {
    return scheduler_.take(unit, now, max, out);
  }
  bool postpone(RayContext& ray, uint32_t treelet, Cycle now) override {
    bool queued = scheduler_.postpone(ray, treelet, now);
    if (queued) work_.notify(sc_core::SC_ZERO_TIME);
    return queued;
  }
  void retire(RayContext& ray, Cycle now) override {
    scheduler_.retire(ray, now);
    work_.notify(sc_core::SC_ZERO_TIME);
  }
  bool exhausted() const override { return scheduler_.exhausted(); }

 private:
  TreeletScheduler& scheduler_;
  sc_core::sc_event& work_;
};

TreeletQueueModule::TreeletQueueModule(sc_core::sc_module_name name,
                                       const TreeletQueueConfig& config, uint32_t treelets,
                                       std::vector<uint32_t> root_treelets,
                                       const RayContextPool& pool, uint32_t state_bytes)
    : sc_module(name),
      in("in"),
      out("out"),
      config_(config),
      treelets_(treelets),
      roots_(std::move(root_treelets)),
      pool_(pool),
      state_bytes_(state_bytes),
      work_("work") {
  out.bind(*this);
}

void TreeletQueueModule::end_of_elaboration() {
  upstream_ = &in->supply();
  scheduler_ = std::make_unique<TreeletScheduler>(config_, treelets_, roots_, *upstream_, pool_,
                                                  state_bytes_);
  notifying_ = std::make_unique<Notifying>(*scheduler_, work_);
}

RaySupply& TreeletQueueModule::supply() {
  return *notifying_;
}

std::string TreeletQueueModule::dump() const {
  std::ostringstream out;
  out << name() << ": " << scheduler_->queued() << " rays queued, " << scheduler_->executing()
      << " executing, dispatcher " << (upstream_->exhausted() ? "exhausted" : "has rays") << "\n";
  return out.str();
}

}  // namespace rtsim
