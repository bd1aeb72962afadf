#include "model/fidelity/scaled_level.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <functional>
#include <random>

#include <fmt/format.h>

#include "model/fidelity/cache_hierarchy.h"
#include "model/fidelity/l2_warming.h"
#include "model/fidelity/ray_charge.h"
#include "model/fidelity/ray_range_reader.h"
#include "model/fidelity/systematic.h"
#include "model/sc/rt_simulator.h"
#include "model/sched/ray_source.h"

namespace rtsim {
namespace {

uint32_t scaled_count(uint32_t count, double share) {
  return std::max(1u, uint32_t(double(count) * share));
}

using Field = std::function<double(const CostTotals&)>;

// One estimate's series: y / x (or a total of y) over the rays of one type, or of all (-1).
struct Metric {
  Field y, x;
  int type = -1;
  SystematicSeries series;
};

// The units of the sample (warps) as their rays retire, handed on complete and in stream order
// so that successive differences are taken between neighbouring warps.
class WarpCollector : public RayRetireListener {
 public:
  WarpCollector(uint64_t rays, uint64_t unit_rays, std::vector<Metric>& metrics)
      : rays_(rays), unit_rays_(unit_rays), metrics_(metrics) {}

  void retired(const RayContext& ray, Cycle now) override {
    uint64_t unit = ray.sequence / unit_rays_;
    while (pending_.size() <= unit - first_) pending_.emplace_back();
    Pending& p = pending_[unit - first_];
    charge_retired_ray(p.by_type, ray, now);
    ++p.retired;
    while (!pending_.empty() && pending_.front().retired == unit_size(first_)) {
      finish(pending_.front());
      pending_.pop_front();
      ++first_;
    }
  }

  const std::array<CostTotals, kRayTypeCount>& totals() const { return totals_; }

 private:
  struct Pending {
    uint64_t retired = 0;
    std::array<CostTotals, kRayTypeCount> by_type{};
  };

  uint64_t unit_size(uint64_t unit) const {
    return std::min(unit_rays_, rays_ - unit * unit_rays_);
  }

  void finish(const Pending& p) {
    for (int t = 0; t < kRayTypeCount; ++t) totals_[t] += p.by_type[t];
    for (Metric& m : metrics_) {
      double y = 0, x = 0;
      for (int t = 0; t < kRayTypeCount; ++t) {
        if (m.type >= 0 && t != m.type) continue;
        y += m.y(p.by_type[t]);
        if (m.x) x += m.x(p.by_type[t]);
      }
      m.series.add(y, x);
    }
  }

  uint64_t rays_, unit_rays_;
  std::vector<Metric>& metrics_;
  std::deque<Pending> pending_;
  uint64_t first_ = 0;  // the unit at pending_.front()
  std::array<CostTotals, kRayTypeCount> totals_{};
};

const Field kRays = [](const CostTotals& c) { return double(c.rays); };
const Field kWork = [](const CostTotals& c) { return double(c.nodes + c.triangles); };
const Field kNodes = [](const CostTotals& c) { return double(c.nodes); };
const Field kTriangles = [](const CostTotals& c) { return double(c.triangles); };
const Field kDram = [](const CostTotals& c) { return double(c.reads.dram_bytes); };
const Field kLatency = [](const CostTotals& c) { return c.latency; };

// The estimates of each scope (each ray type, then all rays), in this order, then each cache
// level's hit rate; after every scope's: the totals of all rays (work, then DRAM bytes).
enum MetricIndex { kNodesPerRay, kTrianglesPerRay, kDramPerRay, kLatencyPerRay, kLevelRates };

struct Metrics {
  size_t levels = 0;
  std::vector<Metric> all;
  size_t per_scope() const { return kLevelRates + levels; }
  size_t work_total() const { return (kRayTypeCount + 1) * per_scope(); }
  size_t dram_total() const { return work_total() + 1; }
  const SystematicSeries& series(int scope, size_t index) const {
    return all[size_t(scope) * per_scope() + index].series;
  }
};

Metrics make_metrics(size_t levels) {
  Metrics m{levels, {}};
  for (int scope = 0; scope <= kRayTypeCount; ++scope) {
    int type = scope < kRayTypeCount ? scope : -1;
    m.all.push_back({kNodes, kRays, type, {}});
    m.all.push_back({kTriangles, kRays, type, {}});
    m.all.push_back({kDram, kRays, type, {}});
    m.all.push_back({kLatency, kRays, type, {}});
    for (size_t i = 0; i < levels; ++i)
      m.all.push_back({[i](const CostTotals& c) { return double(c.reads.hits[i]); },
                       [i](const CostTotals& c) { return double(c.reads.accesses[i]); },
                       type,
                       {}});
  }
  m.all.push_back({kWork, {}, -1, {}});
  m.all.push_back({kDram, {}, -1, {}});
  return m;
}

// First references to the first shared level's blocks in one scope (a ray type, or all rays):
// those the scaled machine fetched (cold misses) and those an absent unit of the full machine had
// fetched.
struct FirstReferences {
  double fetched = 0, absent = 0;
};

// What to add to k x the scaled machine's DRAM bytes: its fetched first references are paid
// once, not k times, and the absent units' ones once too.
double dram_offset(double k, const FirstReferences& first, double block) {
  return (first.absent - (k - 1) * first.fetched) * block;
}

// The estimates of one scope; k: the scale-up; first: the first references of the first shared
// level S (scale.first_shared; none: no level is shared and every count scales by k). The full
// machine fetches each first-referenced block once: its hits at S = k h + (k - 1) fetched -
// absent, and the levels below S see S's first fetches once, not k times: their accesses are
// k a - (k - 1) fetched + absent. DRAM bytes as dram_offset. Levels above S scale by k.
TypeEstimate scope_estimates(const Metrics& metrics, int scope, double k, const ScaleModel& scale,
                             const FirstReferences& first, const std::vector<std::string>& names,
                             double block) {
  TypeEstimate e;
  e.nodes_per_ray = metrics.series(scope, kNodesPerRay).ratio(k);
  e.triangles_per_ray = metrics.series(scope, kTrianglesPerRay).ratio(k);
  uint32_t s = scale.first_shared;
  for (uint32_t i = 0; i < names.size(); ++i) {
    const SystematicSeries& rate = metrics.series(scope, kLevelRates + i);
    e.levels.push_back({names[i], i < s ? rate.ratio(k)
                                  : i == s
                                      ? rate.ratio(k, (k - 1) * first.fetched - first.absent)
                                      : rate.ratio(k, 0, first.absent - (k - 1) * first.fetched)});
  }
  e.dram_bytes_per_ray = metrics.series(scope, kDramPerRay).ratio(k, dram_offset(k, first, block));
  e.latency_mean = metrics.series(scope, kLatencyPerRay).ratio(k);
  return e;
}

// The scaled machine's RT units: the full machine's over the rate, to the nearest (at least 1).
uint32_t scaled_units(uint32_t units, uint32_t rate) {
  return std::max(1u, uint32_t(std::lround(double(units) / double(std::max(rate, 1u)))));
}

// Why the plain scale model's cache and DRAM figures may read low, or nothing. In expectation
// the whole stream reads at most k times the distinct blocks the sampled warps read (a block
// only one warp reads is drawn with odds 1 in k), so if that fits the largest level from the
// first shared one down, the full machine has no capacity misses that lines outside the sample
// would cause; otherwise it may (model/fidelity/README.md).
std::string capacity_caveat(double k, const CacheStats& paying, const HwConfig& config,
                            uint32_t from) {
  const MemoryLevelConfig* largest = &config.memory[from];
  for (size_t i = from; i < config.memory.size(); ++i)
    if (config.memory[i].cache.size_bytes > largest->cache.size_bytes) largest = &config.memory[i];
  double sampled = double(paying.cold_misses + paying.absent_fills) *
                   double(block_bytes(config.memory[from].cache));
  double size = double(largest->cache.size_bytes);
  if (k * sampled <= size) return {};
  return fmt::format(
      "cache and DRAM figures (and cycles) may read low: the sampled warps read {:.3g} MiB of "
      "distinct blocks, the whole stream up to {:.3g} times that ({:.3g} MiB) against the {:.3g} "
      "MiB of memory.{}, and its capacity misses of lines no sampled warp reads are not counted "
      "(--sample-method warmed counts them)",
      sampled / 1048576, k, k * sampled / 1048576, size / 1048576, largest->name);
}

// A block's fetch at level `level` with no other load: the tag checks from there down, the
// links between them each way, the DRAM's unloaded latency and the block's transfer. The absent
// units' first fetches are taken to last that long until the level has measured fetches of its
// own.
Cycle unloaded_fetch_cycles(const HwConfig& config, uint32_t level) {
  double cycles =
      unloaded_dram_read(dram_for_analysis(config), block_bytes(last_level(config).cache));
  for (size_t i = level; i < config.memory.size(); ++i) {
    cycles += config.memory[i].cache.hit_latency;
    if (i + 1 < config.memory.size()) cycles += 2.0 * config.memory[i].link.latency;
  }
  return Cycle(std::ceil(cycles));
}

}  // namespace

std::vector<uint64_t> scale_model_warps(uint64_t warps, uint32_t rate, uint32_t units,
                                        uint64_t seed) {
  // Each scaled unit gets warps with the odds a unit of the full machine has: 1 in units.
  double odds = double(scaled_units(units, rate)) / double(units);
  uint64_t spacing = std::max(1u, std::min(rate, units));
  uint64_t offset = (seed / spacing * spacing) % rate;  // which blocks, when rate > units
  std::mt19937_64 rng(seed);
  std::vector<uint64_t> out;
  for (uint64_t w = 0; w < warps; ++w) {
    uint64_t block = w / (kBlockWarps * spacing);
    if (rate > units && (block * spacing + offset) % rate >= spacing) continue;
    if (double(rng() >> 11) * 0x1.0p-53 < odds) out.push_back(w);
  }
  return out;
}

ScaleModel scale_model(const HwConfig& config, uint32_t rate) {
  ScaleModel m;
  m.config = config;
  HwConfig& c = m.config;
  c.rt_units = scaled_units(config.rt_units, rate);
  m.machine_share = double(c.rt_units) / double(config.rt_units);
  c.dispatch.rays_per_cycle = config.dispatch.rays_per_cycle * m.machine_share;
  m.first_shared = uint32_t(config.memory.size());
  for (uint32_t i = 0; i < config.memory.size(); ++i) {
    const MemoryLevelConfig& full = config.memory[i];
    MemoryLevelConfig& level = c.memory[i];
    // An instance of the scaled machine serves fewer units than the full machine's where the
    // scaled machine has fewer units than one full instance: a shared level, or a group level
    // larger than the scaled machine. It keeps its size; its MSHRs scale with its units.
    double share = double(units_per_instance(level, c.rt_units)) /
                   double(units_per_instance(full, config.rt_units));
    m.level_share.push_back(share);
    if (share < 1) level.cache.mshrs = scaled_count(full.cache.mshrs, share);
    if (level.scope == LevelScope::Shared && m.first_shared == config.memory.size())
      m.first_shared = i;
  }
  c.dram.bytes_per_cycle = config.dram.bytes_per_cycle * m.machine_share;
  c.dram.queue_depth = scaled_count(config.dram.queue_depth, m.machine_share);
  c.banked_dram.channels = scaled_count(config.banked_dram.channels, m.machine_share);
  c.treelet_queues.max_rays = scaled_count(config.treelet_queues.max_rays, m.machine_share);
  c.sort.buffer_rays =
      std::max(c.rt.warp_size, scaled_count(config.sort.buffer_rays, m.machine_share));
  return m;
}

FidelityResult run_scaled_level(const HwConfig& config, BvhView image, const std::string& stream,
                                const SamplingConfig& sampling) {
  setenv("SYSC_DISABLE_COPYRIGHT_MESSAGE", "1", 1);
  HostTimer timer;
  RayRangeReader reader(stream);
  uint64_t total = reader.header().total_rays();
  uint32_t rate = std::max<uint32_t>(sampling.rate, 1);
  check_sample_rate(total, rate);
  uint64_t unit = std::min<uint64_t>(config.rt.warp_size, total / (2ull * rate));
  uint64_t warps = (total + unit - 1) / unit;
  std::vector<Ray> rays;
  std::vector<uint64_t> drawn = scale_model_warps(warps, rate, config.rt_units, sampling.seed);
  for (uint64_t w : drawn) reader.read(w * unit, (w + 1) * unit, rays);

  ScaleModel model = scale_model(config, rate);
  std::vector<std::string> names = level_names(config.memory);
  Metrics metrics = make_metrics(names.size());
  WarpCollector collector(rays.size(), unit, metrics.all);
  bool warmed = sampling.method == SampleMethod::Warmed;
  WarmingSource source(rays, drawn, unit, reader, image, config, model.config);
  RtSimulator sim(model.config, image, source, 0, 0, &collector);
  if (warmed)
    source.warm(sim);
  else if (model.first_shared < names.size())
    sim.share_first_references(model.first_shared, model.machine_share,
                               unloaded_fetch_cycles(config, model.first_shared));
  sim.run();

  FidelityResult r;
  r.level = FidelityLevel::Sampled;
  r.sample_rate = rate;
  r.sample_method = sample_method_name(sampling.method);
  r.rays = total;
  r.simulated_rays = r.measured_rays = rays.size();
  r.strata = uint32_t(metrics.all[metrics.work_total()].series.units());
  r.clock_ghz = config.clock_ghz;
  r.time_model =
      "scale model: 1 in " + std::to_string(rate) + " warps (seed " +
      std::to_string(sampling.seed) + ") on " + std::to_string(model.config.rt_units) + " of " +
      std::to_string(config.rt_units) + " RT units" +
      (warmed ? ", the other units' reads warming memory." + last_level(config).name : "");
  double k = double(total) / double(rays.size());

  // The first shared level's first references, shared out over the ray types: the fetched
  // ones by the type's misses there, the absent units' ones by its accesses. Warmed (a unit level
  // and one shared level), every fetch of the shared level is counted where it was made: the
  // scaled units' (their DRAM bytes over the block) once, the absent units' by their rays' types.
  const auto& totals = collector.totals();
  uint32_t shared = model.first_shared;
  bool sharing = shared < names.size() && model.level_share[shared] < 1;
  CacheStats first_stats = sharing ? sim.level_stats(shared) : CacheStats{};
  double block = double(block_bytes(config.memory[sharing ? shared : names.size() - 1].cache));
  if (!warmed && sharing) r.caveat = capacity_caveat(k, first_stats, config, shared);
  double misses = 0, accesses = 0;
  for (const CostTotals& c : totals)
    if (sharing) {
      misses += double(c.reads.misses(shared));
      accesses += double(c.reads.accesses[shared]);
    }
  auto first_of = [&](int t) {
    const CostTotals& c = totals[t];
    if (!sharing) return FirstReferences{};
    if (warmed) return FirstReferences{double(c.reads.dram_bytes) / block, source.fetched()[t]};
    return FirstReferences{
        misses > 0 ? double(first_stats.cold_misses) * double(c.reads.misses(shared)) / misses : 0,
        accesses > 0
            ? double(first_stats.absent_fills) * double(c.reads.accesses[shared]) / accesses
            : 0};
  };
  FirstReferences first_all;
  for (int t = 0; t < kRayTypeCount; ++t) {
    FirstReferences f = first_of(t);
    first_all = {first_all.fetched + f.fetched, first_all.absent + f.absent};
  }
  for (int t = 0; t < kRayTypeCount; ++t) {
    if (totals[t].rays > 0)
      r.types[t] = scope_estimates(metrics, t, k, model, first_of(t), names, block);
    r.types[t].rays = reader.header().counts[t];
  }
  TypeEstimate all = scope_estimates(metrics, kRayTypeCount, k, model, first_all, names, block);
  r.nodes_per_ray = all.nodes_per_ray;
  r.triangles_per_ray = all.triangles_per_ray;
  r.levels = all.levels;
  r.dram_bytes =
      metrics.all[metrics.dram_total()].series.total(k, dram_offset(k, first_all, block));

  double latency = all.latency_mean.value;
  // Full-machine time over the scaled machine's: the stream's share of the work it did (k x
  // the share of the machine); about 1 when rate <= rt.count, rate / rt.count above.
  double time_factor = k * model.machine_share;
  double cycles = (double(sim.cycles()) - latency) * time_factor + latency;
  Estimate work = metrics.all[metrics.work_total()].series.total(k);
  r.cycles = {true, cycles, work.value > 0 ? cycles * work.ci95 / work.value : 0.0};
  timer.stop(r);
  return r;
}

}  // namespace rtsim
