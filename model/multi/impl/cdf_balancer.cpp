#include "model/multi/impl/cdf_balancer.h"

#include <numeric>
#include <stdexcept>

namespace rtsim::multi {

CdfBalancer::CdfBalancer(Work work, uint32_t devices, uint32_t positions)
    : work_(work), devices_(devices), positions_(positions), measured_(devices, 0.0) {
  if (devices == 0) throw std::invalid_argument("CdfBalancer: no devices");
}

std::vector<double> CdfBalancer::speeds() const {
  double known_sum = 0;
  int known = 0;
  for (double p : measured_)
    if (p > 0) known_sum += p, ++known;
  double fallback = known > 0 ? known_sum / known : 1.0;
  std::vector<double> speeds;
  for (double p : measured_) speeds.push_back(p > 0 ? p : fallback);
  return speeds;
}

namespace {

double expected_cost(const TypedRays& rays, const std::array<double, kRayTypeCount>& type_cost) {
  double cost = 0;
  for (int t = 0; t < kRayTypeCount; ++t) cost += double(rays[t]) * type_cost[t];
  return cost;
}

}  // namespace

std::vector<double> CdfBalancer::predicted_cost(const FramePreview& next) const {
  std::vector<double> cost(positions_);
  for (uint32_t p = 0; p < positions_; ++p) {
    double factor = pixel_factor_[p] > 0 ? pixel_factor_[p] : 1.0;
    cost[p] = factor * expected_cost(next.rays[p], type_cost_);
  }
  return cost;
}

Split CdfBalancer::next_split(const FramePreview& next) const {
  if (weights_.empty()) {
    double total = std::accumulate(next.samples.begin(), next.samples.end(), 0.0);
    if (next.samples.size() != positions_ || !(total > 0))
      return equal_area_split(positions_, devices_);
    return split_by_cdf(next.samples, balanced_shares(speeds(), total));
  }
  bool predict = work_ == Work::CurrentCost && next.rays.size() == positions_ &&
                 pixel_factor_.size() == positions_;
  std::vector<double> predicted = predict ? predicted_cost(next) : std::vector<double>{};
  const std::vector<double>& weights = predict ? predicted : weights_;
  double total = std::accumulate(weights.begin(), weights.end(), 0.0);
  if (!(total > 0)) {  // nothing to balance on: split the area by speed
    std::vector<double> area(positions_, 1.0);
    return split_by_cdf(area, balanced_shares(speeds(), double(positions_)));
  }
  return split_by_cdf(weights, balanced_shares(speeds(), total));
}

void CdfBalancer::observe(const FrameFeedback& frame) {
  if (frame.devices.size() != devices_)
    throw std::invalid_argument("CdfBalancer::observe: one DeviceWork per device expected");
  for (uint32_t i = 0; i < devices_; ++i) {
    const DeviceWork& d = frame.devices[i];
    double work = work_ == Work::Samples ? d.samples : d.cost;
    if (work > 0 && d.time_ns > 0) measured_[i] = work / d.time_ns;  // p_i
  }
  const std::vector<double>& weights = work_ == Work::Samples ? frame.samples : frame.cost;
  if (weights.size() == positions_) weights_ = weights;
  if (work_ != Work::CurrentCost || frame.rays.size() != positions_ ||
      frame.cost.size() != positions_)
    return;
  bool known = false;
  for (int t = 0; t < kRayTypeCount; ++t) known |= frame.type_cost[t] > 0;
  if (!known) return;
  type_cost_ = frame.type_cost;
  pixel_factor_.resize(positions_, 0.0);
  for (uint32_t p = 0; p < positions_; ++p) {
    double expected = expected_cost(frame.rays[p], type_cost_);
    if (expected > 0) pixel_factor_[p] = frame.cost[p] / expected;
  }
}

}  // namespace rtsim::multi
