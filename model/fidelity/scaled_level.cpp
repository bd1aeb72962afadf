#include "model/fidelity/scaled_level.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <functional>
#include <random>

#include <fmt/format.h>

#include "model/fidelity/ray_charge.h"
#include "model/fidelity/l2_warming.h"
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
const Field kL1Hits = [](const CostTotals& c) { return double(c.reads.hits[0]); };
const Field kL1Accesses = [](const CostTotals& c) { return double(c.reads.accesses[0]); };
const Field kL2Hits = [](const CostTotals& c) { return double(c.reads.hits[1]); };
const Field kL2Accesses = [](const CostTotals& c) { return double(c.reads.accesses[1]); };
const Field kDram = [](const CostTotals& c) { return double(c.reads.dram_bytes); };
const Field kLatency = [](const CostTotals& c) { return c.latency; };

// The estimates of each scope (each ray type, then all rays), in this order.
enum MetricIndex {
  kNodesPerRay,
  kTrianglesPerRay,
  kL1Rate,
  kL2Rate,
  kDramPerRay,
  kLatencyPerRay,
  kPerScope
};
// After every scope's estimates: the totals of all rays.
constexpr size_t kWorkTotal = (kRayTypeCount + 1) * kPerScope, kDramTotal = kWorkTotal + 1;

std::vector<Metric> make_metrics() {
  std::vector<Metric> metrics;
  for (int scope = 0; scope <= kRayTypeCount; ++scope) {
    int type = scope < kRayTypeCount ? scope : -1;
    metrics.push_back({kNodes, kRays, type, {}});
    metrics.push_back({kTriangles, kRays, type, {}});
    metrics.push_back({kL1Hits, kL1Accesses, type, {}});
    metrics.push_back({kL2Hits, kL2Accesses, type, {}});
    metrics.push_back({kDram, kRays, type, {}});
    metrics.push_back({kLatency, kRays, type, {}});
  }
  metrics.push_back({kWork, {}, -1, {}});
  metrics.push_back({kDram, {}, -1, {}});
  return metrics;
}

// First references to L2 lines in one scope (a ray type, or all rays): those the scaled
// machine fetched (cold misses) and those an absent unit of the full machine had fetched.
struct FirstReferences {
  double fetched = 0, absent = 0;
};

// What to add to k x the scaled machine's DRAM bytes: its fetched first references are paid
// once, not k times, and the absent units' ones once too.
double dram_offset(double k, const FirstReferences& first, double line) {
  return (first.absent - (k - 1) * first.fetched) * line;
}

const SystematicSeries& series(const std::vector<Metric>& metrics, int scope, int index) {
  return metrics[size_t(scope) * kPerScope + size_t(index)].series;
}

// The estimates of one scope; k: the scale-up, line: the L2's line size. The full machine
// fetches each first-referenced line once: DRAM bytes = k (D - fetched x line) + (fetched +
// absent) x line, and its L2 hits = k h + (k - 1) fetched - absent.
TypeEstimate scope_estimates(const std::vector<Metric>& metrics, int scope, double k,
                             const FirstReferences& first, double line) {
  TypeEstimate e;
  e.nodes_per_ray = series(metrics, scope, kNodesPerRay).ratio(k);
  e.triangles_per_ray = series(metrics, scope, kTrianglesPerRay).ratio(k);
  e.l1_hit_rate = series(metrics, scope, kL1Rate).ratio(k);
  e.l2_hit_rate = series(metrics, scope, kL2Rate).ratio(k, (k - 1) * first.fetched - first.absent);
  e.dram_bytes_per_ray = series(metrics, scope, kDramPerRay).ratio(k, dram_offset(k, first, line));
  e.latency_mean = series(metrics, scope, kLatencyPerRay).ratio(k);
  return e;
}

// The scaled machine's RT units: the full machine's over the rate, to the nearest (at least 1).
uint32_t scaled_units(uint32_t units, uint32_t rate) {
  return std::max(1u, uint32_t(std::lround(double(units) / double(std::max(rate, 1u)))));
}

// Why the plain scale model's L2 and DRAM figures may read low, or nothing. In expectation the
// whole stream reads at most k times the distinct blocks the sampled warps read (a block only
// one warp reads is drawn with odds 1 in k), so if that fits the L2 the full machine has no
// capacity misses that lines outside the sample would cause; otherwise it may
// (model/fidelity/README.md).
std::string capacity_caveat(double k, const CacheStats& l2, const CacheConfig& config) {
  double sampled = double(l2.cold_misses + l2.absent_fills) * double(block_bytes(config));
  if (k * sampled <= double(config.size_bytes)) return {};
  return fmt::format(
      "L2 and DRAM figures (and cycles) may read low: the sampled warps read {:.3g} MiB of "
      "distinct blocks, the whole stream up to {:.3g} times that ({:.3g} MiB) against an L2 of "
      "{:.3g} MiB, and its capacity misses of lines no sampled warp reads are not counted "
      "(--sample-method warmed counts them)",
      sampled / 1048576, k, k * sampled / 1048576, double(config.size_bytes) / 1048576);
}

// A block's fetch at the L2 with no other load: its tag check, the DRAM's unloaded latency and
// the block's transfer. The absent units' first fetches are taken to last that long until the
// L2 has measured fetches of its own.
Cycle unloaded_fetch_cycles(const HwConfig& config) {
  return last_level(config).cache.hit_latency +
         Cycle(std::ceil(
             unloaded_dram_read(dram_for_analysis(config), block_bytes(last_level(config).cache))));
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
  last_level(c).cache.mshrs = scaled_count(last_level(config).cache.mshrs, m.machine_share);
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
  std::vector<Metric> metrics = make_metrics();
  WarpCollector collector(rays.size(), unit, metrics);
  bool warmed = sampling.method == SampleMethod::Warmed;
  WarmingSource source(rays, drawn, unit, reader, image, config, model.config);
  RtSimulator sim(model.config, image, source, 0, 0, &collector);
  if (warmed)
    source.warm(sim);
  else
    sim.share_l2_first_references(model.machine_share, unloaded_fetch_cycles(config));
  sim.run();

  FidelityResult r;
  r.level = FidelityLevel::Sampled;
  r.sample_rate = rate;
  r.sample_method = sample_method_name(sampling.method);
  r.rays = total;
  r.simulated_rays = r.measured_rays = rays.size();
  r.strata = uint32_t(metrics[kWorkTotal].series.units());
  r.clock_ghz = config.clock_ghz;
  r.time_model = "scale model: 1 in " + std::to_string(rate) + " warps (seed " +
                 std::to_string(sampling.seed) + ") on " + std::to_string(model.config.rt_units) +
                 " of " + std::to_string(config.rt_units) + " RT units" +
                 (warmed ? ", the other units' reads warming the L2" : "");
  double k = double(total) / double(rays.size());

  // First references, shared out over the ray types: the fetched ones by their L2 misses,
  // the absent units' ones by their L2 accesses. Warmed, every fetch is counted where it was
  // made: the scaled units' (their DRAM bytes over the block) once, the absent units' by their
  // rays' types.
  CacheStats l2 = sim.l2_stats();
  if (!warmed) r.caveat = capacity_caveat(k, l2, last_level(config).cache);
  double line = double(block_bytes(last_level(config).cache));
  const auto& totals = collector.totals();
  double misses = 0, accesses = 0;
  for (const CostTotals& c : totals) {
    misses += double(c.reads.misses(1));
    accesses += double(c.reads.accesses[1]);
  }
  // A type's first references: warmed, its own fetches and its absent units'; otherwise the
  // run's cold misses and absent fills shared out by the type's L2 misses and accesses.
  auto first_of = [&](int t) {
    const CostTotals& c = totals[t];
    if (warmed) return FirstReferences{double(c.reads.dram_bytes) / line, source.fetched()[t]};
    return FirstReferences{
        misses > 0 ? double(l2.cold_misses) * double(c.reads.misses(1)) / misses : 0,
        accesses > 0 ? double(l2.absent_fills) * double(c.reads.accesses[1]) / accesses : 0};
  };
  FirstReferences first_all;
  for (int t = 0; t < kRayTypeCount; ++t) {
    FirstReferences f = first_of(t);
    first_all = {first_all.fetched + f.fetched, first_all.absent + f.absent};
  }
  for (int t = 0; t < kRayTypeCount; ++t) {
    uint64_t rays_of_type = reader.header().counts[t];
    const CostTotals& c = totals[t];
    FirstReferences first = first_of(t);
    if (c.rays > 0) r.types[t] = scope_estimates(metrics, t, k, first, line);
    r.types[t].rays = rays_of_type;
  }
  TypeEstimate all = scope_estimates(metrics, kRayTypeCount, k, first_all, line);
  r.nodes_per_ray = all.nodes_per_ray;
  r.triangles_per_ray = all.triangles_per_ray;
  r.l1_hit_rate = all.l1_hit_rate;
  r.l2_hit_rate = all.l2_hit_rate;
  r.dram_bytes = metrics[kDramTotal].series.total(k, dram_offset(k, first_all, line));

  double latency = all.latency_mean.value;
  // Full-machine time over the scaled machine's: the stream's share of the work it did (k x
  // the share of the machine); about 1 when rate <= rt.count, rate / rt.count above.
  double time_factor = k * model.machine_share;
  double cycles = (double(sim.cycles()) - latency) * time_factor + latency;
  Estimate work = metrics[kWorkTotal].series.total(k);
  r.cycles = {true, cycles, work.value > 0 ? cycles * work.ci95 / work.value : 0.0};
  timer.stop(r);
  return r;
}

}  // namespace rtsim
