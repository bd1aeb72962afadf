// The interfaces around an RT unit, in plain C++ (the SystemC modules in model/sc implement
// them and bind them through ports):
//  - RaySupply: where a unit gets rays and gives them back: the ray dispatcher (per-ray and
//    packet modes) or the treelet scheduler in front of it (treelet mode).
//  - the unit's L1, a MemoryTarget (model/mem/memory_level.h): reads that return the cycle
//    data is ready or report it later, and posted writes for stack spills.
//  - RayRetireListener: who learns of every finished ray (stats, verification).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "model/mem/memory_level.h"
#include "model/sched/ray_context.h"

namespace rtsim {

class RaySupply {
 public:
  virtual ~RaySupply() = default;
  // Appends up to `max` rays for `unit` at cycle `now` to out; returns how many. Each ray's
  // `ready` says when it reaches the unit. 0 with exhausted() false means "not now, later".
  virtual size_t take(uint32_t unit, Cycle now, size_t max, std::vector<RayContext*>& out) = 0;
  // The ray is about to enter `treelet`: true if it was queued there (the unit lets it go),
  // false if the unit must keep traversing it. The dispatcher never postpones.
  virtual bool postpone(RayContext& ray, uint32_t treelet, Cycle now) {
    (void)ray, (void)treelet, (void)now;
    return false;
  }
  // A finished ray, with its final state; the supply owns the context again.
  virtual void retire(RayContext& ray, Cycle now) = 0;
  // True when take() will never return a ray again and nothing behind the supply still works
  // for the unit (a shader core's last shading reads): the unit may then finish.
  virtual bool exhausted() const = 0;
};

class RayRetireListener {
 public:
  virtual ~RayRetireListener() = default;
  virtual void retired(const RayContext& ray, Cycle now) = 0;
};

}  // namespace rtsim
