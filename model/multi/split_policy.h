// Frame split strategies for M devices rendering one frame (Harada & Fujita 2014). A policy
// proposes the split of the next frame and then observes what that frame cost:
//   static    equal-area regions, whatever happened before;
//   balanced  the paper's balancer: p_i = samples processed / time in the previous frame,
//             t = N / sum(p_i), n_i = t * p_i, split found on the CDF of the previous frame's
//             sample distribution over the screen (a sample is a ray, or a camera ray: SampleUnit);
//   cost      the same search, with each sample weighted by its simulated cost (the cycles its
//             rays took) instead of counted;
//   current   an extension: the CDF of the frame about to be traced, whose rays the primary
//             knows once it has generated them (SEED's flow): each ray weighted by the previous
//             frame's mean cost of its ray type, times how much more or less than that mean
//             the rays of its pixel cost in the previous frame; speeds as for cost.
// Contract: next_split() changes nothing; observe() is the only thing that changes a policy.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/multi/frame_split.h"
#include "traces/ray.h"

namespace rtsim::multi {

enum class SplitStrategy { Static, Balanced, Cost, Current };

// What the balancers count as a sample: every ray a device traces (each pass places its own
// samples: shadow, reflection, GI, ...), or camera rays only.
enum class SampleUnit { Rays, Camera };
const char* sample_unit_name(SampleUnit unit);  // rays, camera
std::optional<SampleUnit> sample_unit_from_name(const std::string& name);
const char* strategy_name(SplitStrategy strategy);
std::optional<SplitStrategy> strategy_from_name(const std::string& name);
std::vector<std::string> strategy_names();

// What one device did in a frame: the work the balancers count, and the time it took.
struct DeviceWork {
  double samples = 0;  // samples traced, in the run's SampleUnit
  double cost = 0;     // simulated cost of its samples: the cycles of all rays of its pixels
  double time_ns = 0;  // time tracing them
};

using TypedRays = std::array<float, kRayTypeCount>;  // rays of each RayType at one position

// What is known of a frame before it is traced, once the primary has generated its rays: per
// position (scan order, ScreenLayout::position_of), its samples (in the run's SampleUnit) and
// its rays by type (empty if unknown).
struct FramePreview {
  std::vector<double> samples;
  std::vector<TypedRays> rays;
};

// A finished frame: the split it used, each device's work; per position its samples,
// its rays by type and their simulated cost; the mean cost of a ray of each type.
struct FrameFeedback {
  Split split;
  std::vector<DeviceWork> devices;
  std::vector<double> samples, cost;
  std::vector<TypedRays> rays;
  std::array<double, kRayTypeCount> type_cost{};
};

class SplitPolicy {
 public:
  virtual ~SplitPolicy() = default;
  // The split of the next frame: one region per device, covering every position once.
  virtual Split next_split(const FramePreview& next) const = 0;
  Split next_split() const { return next_split(FramePreview{}); }
  // Learns from a finished frame (its split must have one region per device).
  virtual void observe(const FrameFeedback& frame) = 0;
  // Each device's speed as the policy estimates it (work per ns); empty if it keeps none.
  virtual std::vector<double> speeds() const { return {}; }
};

std::unique_ptr<SplitPolicy> make_split_policy(SplitStrategy strategy, uint32_t devices,
                                               uint32_t positions);

}  // namespace rtsim::multi
