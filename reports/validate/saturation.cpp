#include "reports/validate/saturation.h"

#include <algorithm>
#include <cmath>

namespace rtsim::validation {

HwConfig ceiling_machine(const HwConfig& preset, double rate) {
  HwConfig c = unloaded(preset);
  c.rt_units = 2;
  first_level(c).cache.size_bytes = 4u << 20;
  first_level(c).cache.ways = 16;
  first_level(c).cache.mshrs = std::max(first_level(c).cache.mshrs, 64u);
  c.rt.refill = Refill::Slot;
  c.rt.stack.entries = 64;
  double step = c.dispatch.latency + c.rt.setup_latency + first_level(c).cache.hit_latency +
                std::max(c.rt.box.latency, c.rt.triangle.latency) + c.rt.control_latency + 4;
  c.rt.warps = uint32_t(std::ceil(3 * rate * step / c.rt.warp_size));
  return c;
}

Work stat(const std::string& name) {
  return [name](const SimFigures& run) { return run[name]; };
}

Work per_unit(const std::string& name) {
  return [name](const SimFigures& run) { return run.units_sum(name) / run.units(); };
}

double steady_rate(const SimFigures& n, const SimFigures& twice, const Work& work) {
  return (work(twice) - work(n)) / (twice["cycles"] - n["cycles"]);
}

}  // namespace rtsim::validation
