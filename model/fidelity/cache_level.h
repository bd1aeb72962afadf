// Fidelity level 2, cache-level: the rays of the stream run through the traversal unit with
// the real cache and DRAM models of model/mem (same sizes, lines, ways and replacement as the
// config), but without the SystemC timing model. Rays are dealt to the RT units a warp at a
// time; each unit holds warps x warp_size rays, and the rays in flight step in the order of their
// own clocks (their warp's start plus the latency of their steps so far, below), so the caches
// see the interleaving of many rays in flight as the hardware does: a ray whose fetch went to
// DRAM steps again only after the rays that hit in the L1 took the steps that fit in that time;
// a block that misses in the L1 waits for one of its MSHRs when all are busy, as in the cycle
// model. A warp slot takes a new warp when all its rays are done. Treelet and packet modes are run
// as per-ray traversal here (their scheduling changes the order, which only the cycle level has).
// Any-hit calls read their texels through the L1 after the triangle test, as the cycle model's
// RT core does. Stack spills and refills follow the on-chip depth roughly (entries beyond
// rt.stack.entries spill; an empty on-chip stack with spilled entries refills one entry
// through the L1).
// Each ray's latency is the sum over its steps of the memory latency of its fetch (L1 hit, or
// the wait for an L1 MSHR and the L2 hit or DRAM), the test unit latency and issues, and the
// control latency; the cycles come from the roofline of analytic_time.h.
#pragma once

#include <cstdint>
#include <string>

#include "model/bvh/two_level.h"
#include "model/config/hw_config.h"
#include "model/fidelity/analytic_time.h"
#include "model/fidelity/fidelity_result.h"

namespace rtsim {

// Sees what the RT units' L1s send to the L2, block by block (the L2's block: its sector, or its
// line), in the order the walk sends it: reads of the blocks the L1s missed, and writes (the
// L1s' write-backs of stack spills, or every spill with a write-through L1).
class L2ReferenceSink {
 public:
  virtual ~L2ReferenceSink() = default;
  virtual void reference(uint64_t addr, bool write) = 0;
};

// bounds (optional) receives every resource's lower bound; sink (optional) the L2's references.
FidelityResult run_cache_level(const HwConfig& config, BvhView image, const std::string& stream,
                               AnalyticTime* bounds = nullptr, L2ReferenceSink* sink = nullptr);

}  // namespace rtsim
