#include "model/multi/split_policy.h"

#include "model/multi/impl/cdf_balancer.h"
#include "model/multi/impl/static_split.h"

namespace rtsim::multi {

const char* strategy_name(SplitStrategy strategy) {
  switch (strategy) {
    case SplitStrategy::Static: return "static";
    case SplitStrategy::Balanced: return "balanced";
    case SplitStrategy::Cost: return "cost";
    case SplitStrategy::Current: return "current";
  }
  return "?";
}

std::optional<SplitStrategy> strategy_from_name(const std::string& name) {
  for (SplitStrategy s : {SplitStrategy::Static, SplitStrategy::Balanced, SplitStrategy::Cost,
                          SplitStrategy::Current})
    if (name == strategy_name(s)) return s;
  return std::nullopt;
}

const char* sample_unit_name(SampleUnit unit) {
  return unit == SampleUnit::Rays ? "rays" : "camera";
}

std::optional<SampleUnit> sample_unit_from_name(const std::string& name) {
  for (SampleUnit u : {SampleUnit::Rays, SampleUnit::Camera})
    if (name == sample_unit_name(u)) return u;
  return std::nullopt;
}

std::vector<std::string> strategy_names() {
  return {"static", "balanced", "cost", "current"};
}

std::unique_ptr<SplitPolicy> make_split_policy(SplitStrategy strategy, uint32_t devices,
                                               uint32_t positions) {
  switch (strategy) {
    case SplitStrategy::Balanced:
      return std::make_unique<CdfBalancer>(CdfBalancer::Work::Samples, devices, positions);
    case SplitStrategy::Cost:
      return std::make_unique<CdfBalancer>(CdfBalancer::Work::Cost, devices, positions);
    case SplitStrategy::Current:
      return std::make_unique<CdfBalancer>(CdfBalancer::Work::CurrentCost, devices, positions);
    case SplitStrategy::Static: break;
  }
  return std::make_unique<StaticSplit>(devices, positions);
}

}  // namespace rtsim::multi
