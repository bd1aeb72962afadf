// A cache level's miss-ratio curve from one functional pass (model/fidelity/CURVE.md): the cache
// level's walk (cache_level.h: the traversal, every level as configured, stack spills and
// refills) sends the references arriving at the curved level (by default the level above DRAM)
// to one LRU stack per set count and instance (model/mem/stack_distance.h, Mattson's algorithm
// per set: every associativity at that set count at once), or, sampled, to a miniature cache per
// point (model/mem/mini_cache.h, SHARDS); a victim-filled level, whose read misses take no line
// (so no one recency order serves every capacity), to a real cache per point and instance. Each
// point is the level at one capacity and associativity with the config's line, sectors, slices
// and policy: its block reads, misses, write-backs and the bytes it sends below, as the cycle
// model's caches count them with no timing (an MSHR merge is a hit here). The knee is the point
// farthest below the chord from the first point to the last on log2(capacity) against DRAM bytes
// per ray (Satopaa et al., "Finding a 'Kneedle' in a Haystack", ICDCS workshops 2011). Cycles come
// from the full model at a few points (run_cycle_points) and are interpolated between them
// (fill_cycles).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/bvh/two_level.h"
#include "model/config/hw_config.h"

namespace rtsim {

struct CurveRequest {
  std::vector<uint64_t> capacities;  // bytes: one instance of the level, all its slices
  std::vector<uint32_t> ways;        // associativities (default: the config's)
  uint32_t sample_rate = 1;          // 1: exact stacks; R > 1: miniature caches of 1 line in R
  std::string level;                 // the curved level's name (empty: the level above DRAM)
};

// The index in config.memory of the request's level; throws InputError naming --level if there
// is no such level.
uint32_t curve_level(const HwConfig& config, const CurveRequest& request);

// The full model at one capacity of the curved level, for the points simulated both ways:
// that level's counters over its instances.
struct CyclePoint {
  double cycles = 0;
  uint64_t accesses = 0, misses = 0, merges = 0, read_bytes = 0, writeback_bytes = 0;
  double cpu_seconds = 0;
};

struct CurvePoint {
  uint64_t capacity = 0;  // bytes
  uint32_t ways = 0;
  uint64_t sets_per_slice = 0;
  uint64_t reads = 0;     // block reads arriving at the level (exact: every one is counted)
  double misses = 0;      // block reads that miss (sampled: estimated)
  double writebacks = 0;  // dirty blocks written below
  double miss_ratio = 0, miss_ratio_ci95 = 0;
  // Bytes the level sends below (DRAM for the last level): fetched (a victim level: read through)
  // plus written back; clean evictions to a victim level below are not counted.
  double dram_bytes = 0, dram_bytes_ci95 = 0;
  // Cycles: simulated by the full model here, interpolated from the nearest simulated points,
  // or extrapolated past them; unknown without simulated points.
  enum class Cycles : uint8_t { Unknown, Simulated, Interpolated, Extrapolated } cycles_from{};
  double cycles = 0;
  bool has_cycle_run = false;
  CyclePoint cycle_run;  // when has_cycle_run
  // A simulated point between two others: its cycles interpolated from them, as if it had not
  // been simulated (the interpolation's measured error).
  bool has_check = false;
  double cycles_check = 0;
};

struct CacheCurve {
  std::string level;  // its name
  uint32_t instances = 1;
  uint64_t rays = 0, reads = 0, writes = 0, fills = 0;  // the references arriving at the level
  uint32_t block_bytes = 0, sample_rate = 1;
  std::vector<CurvePoint> points;  // by ways, then capacity
  double cpu_seconds = 0;          // of the pass
};

// Why the pass cannot run on this config (empty if it can): a traversal mode whose order the
// pass does not run (treelet queues, packets).
std::string curve_config_problem(const HwConfig& config);

// Why the request cannot be answered for this config (empty if it can): capacities that give no
// whole number of sets per slice, associativities out of range, a rate the sets do not divide
// by, a rate for a level of several instances or filled by victims (miniatures are one cache,
// filled by their misses).
std::string curve_request_problem(const HwConfig& config, const CurveRequest& request);

// Host bytes the request's caches take at the most (for a request curve_request_problem
// accepts): the pass's stacks or miniatures and its walk's L1s and L2, or, with cycle_runs, the
// full model's caches at the largest capacity, whichever is more (they do not live at once).
uint64_t curve_host_bytes(const HwConfig& config, const CurveRequest& request, bool cycle_runs);

// The pass: the cache level's walk over the stream, every point counted on the way.
CacheCurve run_cache_curve(const HwConfig& config, BvhView image, const std::string& stream,
                           const CurveRequest& request);

// Index of the knee among the points of one associativity (indices into curve.points).
size_t curve_knee(const CacheCurve& curve, const std::vector<size_t>& points);

// The full model with level `level` (an index into config.memory) at this capacity and
// associativity, in a forked child.
CyclePoint run_cycle_point(const HwConfig& config, BvhView image, const std::string& stream,
                           uint32_t level, uint64_t capacity, uint32_t ways);

// Cycles of every point from those with a cycle run, linear in the curve's DRAM bytes: between
// the two simulated points around it (in capacity), or past the outermost two; each point's
// cycles_from says which. Needs two simulated points; sets has_check where it can.
void fill_cycles(CacheCurve& curve, const std::vector<size_t>& points);

}  // namespace rtsim
