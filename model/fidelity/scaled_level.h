// The sampled level's default method, a scale model (the idea of Zatel, ISPASS 2024): one warp
// in every `rate` of the stream runs on a machine with 1/rate of the RT units and of the
// resources they share (dispatch bandwidth, L2 MSHRs, DRAM bandwidth and queue, the treelet
// ray buffer). Each warp is drawn with odds 1 in min(rate, rt.count) by a seeded generator, so
// each unit sees the kind of warp sequence it sees in the full machine and its share of the
// shared bandwidth. There the dispatcher hands a warp to whichever unit frees a slot first, so
// the gaps between a unit's warps are geometric, not a fixed rt.count (measured on Sponza, 4
// units: 28% of a unit's warps directly follow its previous one); a fixed spacing read the L1
// hit rate 3.1 points low and cycles 3.7% high at rate 4, the draw +0.3 points and +0.2%. So the
// scaled machine's cycles estimate the full machine's, from one continuous simulation: no
// windows, no warm-up, one fill and drain. The L2 keeps its full size: the units of the full
// machine share most of what their L2 holds (one unit's miss is the others' hit), so a scaled
// L2 would miss far more (measured: +10% to +90% cycles on Sponza).
//
// When rate exceeds rt.count the scaled machine keeps one unit. It still gets 1 warp in rt.count,
// as a unit of the full machine does, but only in 1 block of kBlockWarps x rt.count warps in
// rate / rt.count: it does rt.count / rate of a unit's share, and its time is scaled by
// rate / rt.count (fill and drain, one mean ray latency, counted once). Spreading its warps
// rate apart instead would lose the coherence of neighbouring warps (measured on mobile pica:
// +3% cycles at rate 8, +15% at 64).
//
// Scale-up: counts by the rate (stream rays over simulated rays). Cold (compulsory) L2 misses
// happen once per line however many units share the L2, so they are not scaled: DRAM bytes =
// k x simulated - (k - 1) x cold bytes, and the L2's hits gain (k - 1) x cold misses. Per ray
// type, cold misses are shared out in proportion to the type's L2 misses. An absent unit's
// first fetch of a block is in flight, in the L2 (Cache::share_first_references), for the mean
// latency of the L2's own fetches (the unloaded fetch latency until one is measured): reads in
// that window merge, neither hit nor miss, as in the full machine, and the merges scale by the
// rate with the other counts. Without it those reads hit and the L2 hit rate read high by most
// of the full machine's merges on first fetches (pica, desktop: its interval held on no seed).
//
// Any hierarchy of cache levels: a unit level stays per unit; a group or shared level keeps its
// size, and where one of its scaled instances serves fewer units than a full instance (a shared
// level; a group larger than the scaled machine) its MSHRs scale with its units. The first
// shared level's first references are shared with the absent units and paid once; the levels
// below it see them once, not k times (model/fidelity/README.md).
//
// Intervals (systematic.h): the sampling error of choosing warps, from the successive
// differences of neighbouring sampled warps; cycles take the relative interval of the warps'
// traversal steps (nodes + triangles), their work. They do not cover the scale model's own bias.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/bvh/two_level.h"
#include "model/config/hw_config.h"
#include "model/fidelity/fidelity_result.h"
#include "model/fidelity/sample_plan.h"

namespace rtsim {

struct ScaleModel {
  HwConfig config;           // the scaled machine
  double machine_share = 1;  // its RT units over the full machine's
  // Per cache level: the units a scaled instance serves over a full-machine instance's.
  std::vector<double> level_share;
  // The first shared level (every level below it is shared too), whose first references are
  // shared with the absent units (Cache::share_first_references) and paid once; the number of
  // levels if none is shared.
  uint32_t first_shared = 0;
};

ScaleModel scale_model(const HwConfig& config, uint32_t rate);

constexpr uint64_t kBlockWarps = 64;

// The sampled warps of a stream of `warps` warps, in stream order: each with odds 1 in
// min(rate, units), drawn by mt19937_64(seed); when rate > units, only in the blocks of
// kBlockWarps x units warps that fall in 1 of every rate / units blocks (chosen by the seed too).
std::vector<uint64_t> scale_model_warps(uint64_t warps, uint32_t rate, uint32_t units,
                                        uint64_t seed);

// Runs the scale model of the stream in this process (SystemC: once per process). Throws
// InputError if the stream is too short for the rate.
FidelityResult run_scaled_level(const HwConfig& config, BvhView image, const std::string& stream,
                                const SamplingConfig& sampling);

}  // namespace rtsim
