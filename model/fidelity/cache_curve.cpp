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
#include "model/mem/slice_hash.h"
#include "model/mem/stack_distance.h"
#include "model/sc/fork_run.h"
#include "model/sc/rt_simulator.h"
#include "model/sched/ray_source.h"
#include "model/sched/stats_registry.h"
#include "traces/error.h"
#include "traces/stream.h"

namespace rtsim {

namespace {

uint64_t sets_per_slice(const MemoryLevelConfig& level, uint64_t capacity, uint32_t ways) {
  return capacity / (uint64_t(level.cache.line_bytes) * ways * level.slices);
}

CacheConfig cache_at(const MemoryLevelConfig& level, uint64_t capacity, uint32_t ways) {
  CacheConfig c = level.cache;
  c.size_bytes = capacity;
  c.ways = ways;
  return c;
}

// Below a point's caches: answers at once; the caches count what they send.
struct Nothing : MemoryTarget, ReadClient {
  Cycle read(uint64_t, uint32_t, Cycle at, ReadClient*, uint64_t, ReadCharge&) override {
    return at;
  }
  void write(uint64_t, uint32_t, Cycle) override {}
  void read_done(uint64_t, Cycle, const ReadCharge&) override {}
};

// One point of a victim level: each instance's slices, real caches placed as the level is.
class VictimPoint {
 public:
  VictimPoint(const HwConfig& c, uint32_t index, uint32_t instances, uint64_t capacity,
              uint32_t ways) {
    const MemoryLevelConfig& level = c.memory[index];
    CacheConfig slice = cache_at(level, capacity / level.slices, ways);
    slices_.resize(instances);
    for (auto& inst : slices_)
      for (uint32_t s = 0; s < level.slices; ++s)
        inst.push_back(std::make_unique<Cache>(slice, &nothing_, cache_place(c.memory, index)));
    line_shift_ = uint32_t(__builtin_ctz(level.cache.line_bytes));
    block_ = block_bytes(level.cache);
  }
  void reference(uint32_t instance, uint64_t addr, LevelReference kind) {
    auto& inst = slices_[instance];
    Cache& slice = *inst[slice_of_line(addr >> line_shift_, uint32_t(inst.size()))];
    now_ += Cycle(1) << 16;  // each reference finds the caches idle
    ReadCharge charge;
    if (kind == LevelReference::Read) slice.read(addr, block_, now_, &nothing_, 0, charge);
    if (kind == LevelReference::Write) slice.write(addr, block_, now_);
    if (kind == LevelReference::Fill) slice.fill(addr, block_, now_);
  }
  CacheStats stats() const {
    CacheStats sum;
    for (const auto& inst : slices_)
      for (const auto& s : inst) sum += s->stats();
    return sum;
  }

 private:
  Nothing nothing_;
  std::vector<std::vector<std::unique_ptr<Cache>>> slices_;
  uint32_t line_shift_ = 0, block_ = 0;
  Cycle now_ = 0;
};

// Receives the walk's references at the curved level: counts them and hands them to the stacks
// (per set count, per instance), the miniatures or a victim level's points.
class CurveSink : public LevelReferenceSink {
 public:
  CurveSink(const HwConfig& c, uint32_t index, uint32_t instances, const CurveRequest& request) {
    const MemoryLevelConfig& level = c.memory[index];
    L2Sets sets{level.cache.line_bytes, block_bytes(level.cache), level.slices, 1};
    uint32_t max_ways = *std::max_element(request.ways.begin(), request.ways.end());
    for (uint32_t ways : request.ways)
      for (uint64_t capacity : request.capacities) {
        if (level.fill == LevelFill::Victim) {
          victims.push_back(std::make_unique<VictimPoint>(c, index, instances, capacity, ways));
          continue;
        }
        if (request.sample_rate > 1) {
          minis.push_back(std::make_unique<MiniCache>(cache_at(level, capacity, ways), level.slices,
                                                      request.sample_rate));
          continue;
        }
        sets.sets_per_slice = sets_per_slice(level, capacity, ways);
        auto& per_instance = stacks[sets.sets_per_slice];
        while (per_instance.size() < instances)
          per_instance.push_back(std::make_unique<LruStackSets>(sets, max_ways));
      }
  }
  void reference(uint32_t instance, uint64_t addr, LevelReference kind) override {
    bool write = kind == LevelReference::Write;
    (kind == LevelReference::Read ? reads : write ? writes : fills)++;
    for (auto& point : victims) point->reference(instance, addr, kind);
    if (kind == LevelReference::Fill) return;  // only a victim level is filled
    for (auto& [sets, per_instance] : stacks) per_instance[instance]->reference(addr, write);
    for (auto& mini : minis) mini->reference(addr, write);
  }
  // Read misses and write-backs of a stack point, over the instances.
  std::pair<uint64_t, uint64_t> stack_counts(uint64_t sets, uint32_t ways) const {
    std::pair<uint64_t, uint64_t> sum;
    for (const auto& stack : stacks.at(sets)) {
      sum.first += stack->read_misses(ways);
      sum.second += stack->writebacks(ways);
    }
    return sum;
  }
  // By sets per slice: one stack per instance.
  std::map<uint64_t, std::vector<std::unique_ptr<LruStackSets>>> stacks;
  std::vector<std::unique_ptr<MiniCache>> minis;      // by point
  std::vector<std::unique_ptr<VictimPoint>> victims;  // by point
  uint64_t reads = 0, writes = 0, fills = 0;
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

uint32_t curve_level(const HwConfig& c, const CurveRequest& request) {
  if (request.level.empty()) return uint32_t(c.memory.size() - 1);
  for (uint32_t i = 0; i < c.memory.size(); ++i)
    if (c.memory[i].name == request.level) return i;
  std::string names;
  for (const MemoryLevelConfig& l : c.memory) names += (names.empty() ? "" : ", ") + l.name;
  throw InputError(fmt::format("curve: --level {}: no such cache level (this machine has {})",
                               request.level, names));
}

std::string curve_config_problem(const HwConfig& c) {
  if (c.rt.mode != TraversalMode::DepthFirst)
    return "rt.mode: the curve's pass runs rays depth-first, as the cache level does; use "
           "rt.mode = \"depth_first\"";
  return {};
}

std::string curve_request_problem(const HwConfig& c, const CurveRequest& request) {
  if (request.capacities.empty() || request.ways.empty()) return "no capacities or ways";
  const MemoryLevelConfig& level = c.memory[curve_level(c, request)];
  if (request.sample_rate > 1 && level.fill == LevelFill::Victim)
    return fmt::format(
        "--sample-rate {}: memory.{} is filled by victims, which a miniature cache "
        "is not; curve it exactly (--sample-rate 1)",
        request.sample_rate, level.name);
  if (request.sample_rate > 1 && level_instances(level, c.rt_units) > 1)
    return fmt::format(
        "--sample-rate {}: memory.{} has {} instances and a miniature is one "
        "cache; curve it exactly (--sample-rate 1)",
        request.sample_rate, level.name, level_instances(level, c.rt_units));
  for (uint32_t ways : request.ways) {
    if (ways < 1 || ways > LruStackSets::kMaxWays)
      return fmt::format("{} ways: 1 to {}", ways, LruStackSets::kMaxWays);
    for (uint64_t capacity : request.capacities) {
      uint64_t unit = uint64_t(level.cache.line_bytes) * ways * level.slices;
      if (capacity < unit || capacity % unit != 0)
        return fmt::format(
            "{} bytes with {} ways: not a whole number of sets in each of the {} slices "
            "(a multiple of {} bytes)",
            capacity, ways, level.slices, unit);
      std::string problem = request.sample_rate > 1
                                ? mini_cache_problem(cache_at(level, capacity, ways), level.slices,
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
  uint32_t index = curve_level(c, request), ways = request.ways.front();
  const MemoryLevelConfig& level = c.memory[index];
  uint32_t instances = level_instances(level, c.rt_units);
  // Every level's caches, the curved one at `capacity`.
  auto caches = [&](uint64_t capacity) {
    uint64_t bytes = 0;
    for (uint32_t i = 0; i < c.memory.size(); ++i)
      bytes += level_instances(c.memory[i], c.rt_units) *
               Cache::host_bytes(i == index ? cache_at(level, capacity, ways) : c.memory[i].cache);
    return bytes;
  };
  uint64_t pass = caches(*smallest);  // the walk
  uint32_t max_ways = *std::max_element(request.ways.begin(), request.ways.end());
  std::set<uint64_t> stacks;  // their sets per slice: one stack each per instance
  for (uint32_t w : request.ways)
    for (uint64_t capacity : request.capacities) {
      if (level.fill == LevelFill::Victim) {
        pass += instances * Cache::host_bytes(cache_at(level, capacity, w));
        continue;
      }
      if (request.sample_rate > 1) {
        pass += Cache::host_bytes(cache_at(level, capacity / request.sample_rate, w));
        continue;
      }
      uint64_t sets = sets_per_slice(level, capacity, w);
      if (stacks.insert(sets).second)
        pass += instances * LruStackSets::host_bytes({level.cache.line_bytes,
                                                      block_bytes(level.cache), level.slices, sets},
                                                     max_ways);
    }
  uint64_t full = cycle_runs ? caches(*largest) : 0;
  return std::max(pass, full);
}

CacheCurve run_cache_curve(const HwConfig& config, BvhView image, const std::string& stream,
                           const CurveRequest& request) {
  uint32_t index = curve_level(config, request);
  const MemoryLevelConfig& level = config.memory[index];
  uint32_t instances = level_instances(level, config.rt_units);
  CurveSink sink(config, index, instances, request);
  // The walk's clocks (the order of its references) come from the level at the smallest
  // capacity: there capacity misses are many and the order decides them; at large capacities
  // misses are mostly cold and the order hardly matters (model/fidelity/CURVE.md).
  HwConfig walked = config;
  walked.memory[index].cache =
      cache_at(level, *std::min_element(request.capacities.begin(), request.capacities.end()),
               request.ways.front());
  CacheLevelTaps taps;
  taps.sink = &sink;
  taps.tapped = index;
  FidelityResult walk = run_cache_level(walked, image, stream, taps);
  for (auto& [sets, per_instance] : sink.stacks)
    for (auto& stack : per_instance) stack->finish();
  CacheCurve curve;
  curve.level = level.name;
  curve.instances = instances;
  curve.rays = walk.rays;
  curve.reads = sink.reads;
  curve.writes = sink.writes;
  curve.fills = sink.fills;
  curve.block_bytes = block_bytes(level.cache);
  curve.sample_rate = request.sample_rate;
  curve.cpu_seconds = walk.cpu_seconds;
  double block = curve.block_bytes, reads = double(sink.reads);
  bool write_back = levels_as_built(config)[index].cache.write_back;
  // A write-through level writes every write below; a write-back one its evicted dirty blocks.
  double written = write_back ? 0 : double(sink.writes);
  size_t point = 0;
  for (uint32_t ways : request.ways)
    for (uint64_t capacity : request.capacities) {
      CurvePoint p;
      p.capacity = capacity;
      p.ways = ways;
      p.sets_per_slice = sets_per_slice(level, capacity, ways);
      p.reads = sink.reads;
      if (level.fill == LevelFill::Victim) {
        CacheStats s = sink.victims[point++]->stats();
        p.misses = double(s.misses);
        p.writebacks = write_back ? double(s.writebacks) : written;
      } else if (request.sample_rate > 1) {
        const MiniCache& m = *sink.minis[point++];
        MiniEstimate miss = m.miss_ratio(), dram = m.dram_blocks_per_read();
        p.misses = miss.value * reads;
        p.writebacks = write_back ? (dram.value - miss.value) * reads : written;
        p.miss_ratio_ci95 = miss.ci95;
        p.dram_bytes_ci95 = dram.ci95 * reads * block;
      } else {
        auto [misses, writebacks] = sink.stack_counts(p.sets_per_slice, ways);
        p.misses = double(misses);
        p.writebacks = write_back ? double(writebacks) : written;
      }
      p.miss_ratio = reads > 0 ? p.misses / reads : 0;
      p.dram_bytes = (p.misses + p.writebacks) * block;
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
                           uint32_t level, uint64_t capacity, uint32_t ways) {
  std::string text = run_in_child([&] {
    std::clock_t start = std::clock();
    HwConfig c = config;
    c.memory[level].cache = cache_at(config.memory[level], capacity, ways);
    RayStreamReader reader(stream);
    StreamRaySource source(reader);
    RtSimulator sim(c, image, source);
    sim.run();
    StatsRegistry stats;
    sim.report(stats);
    std::string p = "mem." + config.memory[level].name + ".";
    nlohmann::json out = {{"cycles", double(sim.cycles())},
                          {"accesses", stats.value(p + "accesses")},
                          {"misses", stats.value(p + "misses")},
                          {"merges", stats.value(p + "mshr_merges")},
                          {"read_bytes", stats.value(p + "bytes_below")},
                          {"writeback_bytes", stats.value(p + "writeback_bytes")},
                          {"cpu_seconds", double(std::clock() - start) / CLOCKS_PER_SEC}};
    return out.dump();
  });
  nlohmann::json j = nlohmann::json::parse(text);
  CyclePoint p;
  p.cycles = j["cycles"].get<double>();
  p.accesses = uint64_t(j["accesses"].get<double>());
  p.misses = uint64_t(j["misses"].get<double>());
  p.merges = uint64_t(j["merges"].get<double>());
  p.read_bytes = uint64_t(j["read_bytes"].get<double>());
  p.writeback_bytes = uint64_t(j["writeback_bytes"].get<double>());
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
