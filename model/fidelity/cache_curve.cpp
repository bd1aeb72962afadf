#include "model/fidelity/cache_curve.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <map>
#include <memory>
#include <set>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "model/fidelity/cache_level.h"
#include "model/mem/mini_cache.h"
#include "model/mem/stack_distance.h"
#include "model/sc/fork_run.h"
#include "model/sc/rt_simulator.h"
#include "model/sched/ray_source.h"
#include "traces/error.h"
#include "traces/stream.h"

namespace rtsim {

namespace {

uint64_t sets_per_slice(const HwConfig& c, uint64_t capacity, uint32_t ways) {
  return capacity / (uint64_t(last_level(c).cache.line_bytes) * ways * last_level(c).slices);
}

CacheConfig l2_at(const HwConfig& c, uint64_t capacity, uint32_t ways) {
  CacheConfig l2 = last_level(c).cache;
  l2.size_bytes = capacity;
  l2.ways = ways;
  return l2;
}

// Receives the walk's L2 references: counts them and hands them to the stacks or miniatures.
class CurveSink : public L2ReferenceSink {
 public:
  CurveSink(const HwConfig& c, const CurveRequest& request) {
    L2Sets sets{last_level(c).cache.line_bytes, block_bytes(last_level(c).cache),
                last_level(c).slices, 1};
    uint32_t max_ways = *std::max_element(request.ways.begin(), request.ways.end());
    for (uint32_t ways : request.ways)
      for (uint64_t capacity : request.capacities) {
        if (request.sample_rate > 1) {
          minis.push_back(std::make_unique<MiniCache>(l2_at(c, capacity, ways),
                                                      last_level(c).slices, request.sample_rate));
          continue;
        }
        sets.sets_per_slice = sets_per_slice(c, capacity, ways);
        if (!stacks.count(sets.sets_per_slice))
          stacks.emplace(sets.sets_per_slice, std::make_unique<LruStackSets>(sets, max_ways));
      }
  }
  void reference(uint64_t addr, bool write) override {
    (write ? writes : reads)++;
    for (auto& [sets, stack] : stacks) stack->reference(addr, write);
    for (auto& mini : minis) mini->reference(addr, write);
  }
  std::map<uint64_t, std::unique_ptr<LruStackSets>> stacks;  // by sets per slice
  std::vector<std::unique_ptr<MiniCache>> minis;             // by point
  uint64_t reads = 0, writes = 0;
};

// Cycles at p along the curve's DRAM bytes between simulated points a and b (log2 capacity when
// their DRAM bytes are equal).
double cycles_along(const CurvePoint& p, const CurvePoint& a, const CurvePoint& b) {
  double span = b.dram_bytes - a.dram_bytes, t;
  if (std::abs(span) > 1e-9 * std::max(a.dram_bytes, 1.0))
    t = (p.dram_bytes - a.dram_bytes) / span;
  else
    t = std::log2(double(p.capacity) / a.capacity) / std::log2(double(b.capacity) / a.capacity);
  return a.cycle_run.cycles + t * (b.cycle_run.cycles - a.cycle_run.cycles);
}

}  // namespace

std::string curve_config_problem(const HwConfig& c) {
  if (c.rt.mode != TraversalMode::DepthFirst)
    return "rt.mode: the curve's pass runs rays depth-first, as the cache level does; use "
           "rt.mode = \"depth_first\"";
  return {};
}

std::string curve_request_problem(const HwConfig& c, const CurveRequest& request) {
  if (request.capacities.empty() || request.ways.empty()) return "no capacities or ways";
  for (uint32_t ways : request.ways) {
    if (ways < 1 || ways > LruStackSets::kMaxWays)
      return fmt::format("{} ways: 1 to {}", ways, LruStackSets::kMaxWays);
    for (uint64_t capacity : request.capacities) {
      uint64_t unit = uint64_t(last_level(c).cache.line_bytes) * ways * last_level(c).slices;
      if (capacity < unit || capacity % unit != 0)
        return fmt::format(
            "{} bytes with {} ways: not a whole number of sets in each of the {} slices "
            "(a multiple of {} bytes)",
            capacity, ways, last_level(c).slices, unit);
      std::string problem = request.sample_rate > 1
                                ? mini_cache_problem(l2_at(c, capacity, ways), last_level(c).slices,
                                                     request.sample_rate)
                                : std::string();
      if (!problem.empty())
        return fmt::format("{} bytes with {} ways, 1 line in {}: {}", capacity, ways,
                           request.sample_rate, problem);
    }
  }
  return {};
}

uint64_t curve_host_bytes(const HwConfig& c, const CurveRequest& request, bool cycle_runs) {
  auto [smallest, largest] =
      std::minmax_element(request.capacities.begin(), request.capacities.end());
  uint32_t ways = request.ways.front();
  uint64_t l1s = c.rt_units * Cache::host_bytes(first_level(c).cache);
  uint64_t pass = l1s + Cache::host_bytes(l2_at(c, *smallest, ways));  // the walk
  uint32_t max_ways = *std::max_element(request.ways.begin(), request.ways.end());
  std::set<uint64_t> stacks;  // their sets per slice: one stack each
  for (uint32_t w : request.ways)
    for (uint64_t capacity : request.capacities) {
      if (request.sample_rate > 1) {
        pass += Cache::host_bytes(l2_at(c, capacity / request.sample_rate, w));
        continue;
      }
      uint64_t sets = sets_per_slice(c, capacity, w);
      if (stacks.insert(sets).second)
        pass +=
            LruStackSets::host_bytes({last_level(c).cache.line_bytes,
                                      block_bytes(last_level(c).cache), last_level(c).slices, sets},
                                     max_ways);
    }
  uint64_t full = cycle_runs ? l1s + Cache::host_bytes(l2_at(c, *largest, ways)) : 0;
  return std::max(pass, full);
}

CacheCurve run_cache_curve(const HwConfig& config, BvhView image, const std::string& stream,
                           const CurveRequest& request) {
  std::string problem = two_level_problem(config, "rtsim curve");
  if (!problem.empty()) throw InputError(problem);
  CurveSink sink(config, request);
  // The walk's clocks (the order of its references) come from an L2 of the smallest capacity:
  // there capacity misses are many and the order decides them; at large capacities misses are
  // mostly cold and the order hardly matters (model/fidelity/CURVE.md).
  HwConfig walked = config;
  last_level(walked).cache =
      l2_at(config, *std::min_element(request.capacities.begin(), request.capacities.end()),
            request.ways.front());
  FidelityResult walk = run_cache_level(walked, image, stream, nullptr, &sink);
  for (auto& [sets, stack] : sink.stacks) stack->finish();
  CacheCurve curve;
  curve.rays = walk.rays;
  curve.l2_reads = sink.reads;
  curve.l2_writes = sink.writes;
  curve.block_bytes = block_bytes(last_level(config).cache);
  curve.sample_rate = request.sample_rate;
  curve.cpu_seconds = walk.cpu_seconds;
  double block = curve.block_bytes, reads = double(sink.reads);
  size_t mini = 0;
  for (uint32_t ways : request.ways)
    for (uint64_t capacity : request.capacities) {
      CurvePoint p;
      p.capacity = capacity;
      p.ways = ways;
      p.sets_per_slice = sets_per_slice(config, capacity, ways);
      p.reads = sink.reads;
      // A write-through L2 writes every write below; a write-back one its evicted dirty blocks.
      double written = last_level(config).cache.write_back ? 0 : double(sink.writes);
      if (request.sample_rate > 1) {
        const MiniCache& m = *sink.minis[mini++];
        MiniEstimate miss = m.miss_ratio(), dram = m.dram_blocks_per_read();
        p.misses = miss.value * reads;
        p.writebacks =
            last_level(config).cache.write_back ? (dram.value - miss.value) * reads : written;
        p.miss_ratio = miss.value;
        p.miss_ratio_ci95 = miss.ci95;
        p.dram_bytes =
            (last_level(config).cache.write_back ? dram.value * reads : p.misses + written) * block;
        p.dram_bytes_ci95 = dram.ci95 * reads * block;
      } else {
        const LruStackSets& s = *sink.stacks.at(p.sets_per_slice);
        p.misses = double(s.read_misses(ways));
        p.writebacks = last_level(config).cache.write_back ? double(s.writebacks(ways)) : written;
        p.miss_ratio = reads > 0 ? p.misses / reads : 0;
        p.dram_bytes = (p.misses + p.writebacks) * block;
      }
      curve.points.push_back(p);
    }
  return curve;
}

size_t curve_knee(const CacheCurve& curve, const std::vector<size_t>& points) {
  if (points.size() < 3) return points.front();
  const CurvePoint &first = curve.points[points.front()], &last = curve.points[points.back()];
  double x0 = std::log2(double(first.capacity)), x1 = std::log2(double(last.capacity));
  double drop = first.dram_bytes - last.dram_bytes;
  if (drop <= 0 || x1 <= x0) return points.front();  // flat: the smallest is as good
  size_t knee = points.front();
  double best = 0;
  for (size_t i : points) {
    const CurvePoint& p = curve.points[i];
    double x = (std::log2(double(p.capacity)) - x0) / (x1 - x0);
    double y = (p.dram_bytes - last.dram_bytes) / drop;
    if (1 - x - y > best) best = 1 - x - y, knee = i;  // below the chord (1 - x), normalised
  }
  return knee;
}

CyclePoint run_cycle_point(const HwConfig& config, BvhView image, const std::string& stream,
                           uint64_t capacity, uint32_t ways) {
  std::string text = run_in_child([&] {
    std::clock_t start = std::clock();
    HwConfig c = config;
    last_level(c).cache = l2_at(config, capacity, ways);
    RayStreamReader reader(stream);
    StreamRaySource source(reader);
    RtSimulator sim(c, image, source);
    sim.run();
    CacheStats s = sim.l2_stats();
    nlohmann::json out = {{"cycles", double(sim.cycles())},
                          {"accesses", s.accesses},
                          {"misses", s.misses},
                          {"merges", s.mshr_merges},
                          {"read_bytes", s.bytes_below},
                          {"writeback_bytes", s.writeback_bytes},
                          {"cpu_seconds", double(std::clock() - start) / CLOCKS_PER_SEC}};
    return out.dump();
  });
  nlohmann::json j = nlohmann::json::parse(text);
  CyclePoint p;
  p.cycles = j["cycles"].get<double>();
  p.l2_accesses = j["accesses"].get<uint64_t>();
  p.l2_misses = j["misses"].get<uint64_t>();
  p.l2_merges = j["merges"].get<uint64_t>();
  p.read_bytes = j["read_bytes"].get<uint64_t>();
  p.writeback_bytes = j["writeback_bytes"].get<uint64_t>();
  p.cpu_seconds = j["cpu_seconds"].get<double>();
  return p;
}

void fill_cycles(CacheCurve& curve, const std::vector<size_t>& points) {
  std::vector<size_t> runs;  // the simulated points, by capacity
  for (size_t i : points)
    if (curve.points[i].has_cycle_run) runs.push_back(i);
  for (size_t i : points) {
    CurvePoint& p = curve.points[i];
    if (p.has_cycle_run) {
      p.cycles_from = CurvePoint::Cycles::Simulated;
      p.cycles = p.cycle_run.cycles;
      auto at = size_t(std::find(runs.begin(), runs.end(), i) - runs.begin());
      p.has_check = at > 0 && at + 1 < runs.size();
      if (p.has_check)
        p.cycles_check = cycles_along(p, curve.points[runs[at - 1]], curve.points[runs[at + 1]]);
      continue;
    }
    if (runs.size() < 2) continue;
    size_t hi = 0;  // the first simulated point above p, clamped to [1, last]
    while (hi < runs.size() && curve.points[runs[hi]].capacity < p.capacity) ++hi;
    bool inside = hi > 0 && hi < runs.size();
    hi = std::clamp<size_t>(hi, 1, runs.size() - 1);
    p.cycles = cycles_along(p, curve.points[runs[hi - 1]], curve.points[runs[hi]]);
    p.cycles_from = inside ? CurvePoint::Cycles::Interpolated : CurvePoint::Cycles::Extrapolated;
  }
}

}  // namespace rtsim
