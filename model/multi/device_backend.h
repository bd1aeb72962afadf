// Where the tracing time of a device comes from. The driver (multi_run.h) hands a backend the
// rays each device traces in a frame; the backend says how long each took and what each pixel
// cost. SystemCBackend runs the cycle-approximate model (model/sc/rt_simulator.h) of the
// device's hardware config; tests plug in a backend with a known speed.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "model/config/hw_config.h"
#include "model/multi/frame_split.h"
#include "traces/ray.h"

namespace rtsim::multi {

struct DeviceTask {
  const HwConfig* config = nullptr;  // the device's hardware in this frame
  std::vector<Ray> rays;             // the rays of its region, in stream order
  Region region;                     // the positions whose cost to return
};

struct DeviceResult {
  uint64_t rays = 0, cycles = 0;  // cycles: when the last ray retired
  double time_ns = 0;             // cycles / clock
  std::vector<float> cost;        // per position of the region: the slot cycles of its rays, summed
  std::array<double, kRayTypeCount> type_rays{}, type_cycles{};  // rays and their slot cycles
};

class DeviceBackend {
 public:
  virtual ~DeviceBackend() = default;
  // Simulates every task alone on its hardware; results in task order. A task without rays
  // takes no time.
  virtual std::vector<DeviceResult> run(const std::vector<DeviceTask>& tasks,
                                        const ScreenLayout& layout) = 0;
};

}  // namespace rtsim::multi
