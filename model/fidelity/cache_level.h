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
// The cache levels are the config's, every instance and slice as the cycle model builds them
// (cache_hierarchy.h): a unit's own levels, group and shared levels, victim fills.
// Each ray's latency is the sum over its steps of the memory latency of its fetch (a hit in the
// first level; or the wait for one of its MSHRs, then each level's hit latency and the link to
// it, each way, down to the deepest level the read reached, and DRAM's unloaded read if it went
// there), the test unit latency and issues, and the control latency; the cycles come from the
// roofline of analytic_time.h.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/bvh/two_level.h"
#include "model/config/hw_config.h"
#include "model/fidelity/analytic_time.h"
#include "model/fidelity/cache_hierarchy.h"
#include "model/fidelity/fidelity_result.h"

namespace rtsim {

// What a run of the cache level can hand back besides its result (each optional).
struct CacheLevelTaps {
  AnalyticTime* bounds = nullptr;             // every resource's lower bound
  LevelReferenceSink* sink = nullptr;         // the references arriving at level `tapped`
  uint32_t tapped = 0;                        // an index into config.memory
  std::vector<CacheStats>* levels = nullptr;  // each level's counters, over its instances
};

FidelityResult run_cache_level(const HwConfig& config, BvhView image, const std::string& stream,
                               const CacheLevelTaps& taps = {});

}  // namespace rtsim
