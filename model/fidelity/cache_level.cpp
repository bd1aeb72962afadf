#include "model/fidelity/cache_level.h"

#include <algorithm>
#include <memory>
#include <queue>
#include <stdexcept>
#include <tuple>

#include "model/mem/cache.h"
#include "model/mem/dram.h"
#include "model/sched/hardware_stack.h"
#include "model/sched/shader_core.h"
#include "model/units/traversal.h"
#include "traces/stream.h"

namespace rtsim {
namespace {

// Every read happens this many cycles after the previous one, so each finds the caches idle:
// this level counts hits and misses, it does not time them.
constexpr Cycle kReadGap = 1 << 16;

struct Lane {
  Ray ray;
  TraversalState state;
  bool live = false;
  StackResidency stack;  // its stack entries on chip and in memory
  double latency = 0;
  CostTotals cost;
};

// DRAM as the walk sees it: the one-bus DRAM, every byte read or written counted.
class CountedDram : public MemoryTarget {
 public:
  explicit CountedDram(const DramConfig& config) : dram_(config), target_(dram_) {}
  Cycle read(uint64_t addr, uint32_t bytes, Cycle at, ReadClient* client, uint64_t token,
             ReadCharge& charge) override {
    this->bytes += bytes;
    return target_.read(addr, bytes, at, client, token, charge);
  }
  void write(uint64_t addr, uint32_t bytes, Cycle at) override {
    this->bytes += bytes;
    target_.write(addr, bytes, at);
  }
  uint64_t bytes = 0;

 private:
  Dram dram_;
  DramTarget target_;
};

struct Warp {
  std::vector<Lane> lanes;
  std::vector<uint64_t> shading;  // with the shader model: its hits' shading reads, in order
  uint32_t live = 0;
  double start = 0;    // the clock its rays started at
  double slowest = 0;  // latency of its slowest ray so far
};

// A lane's next step, at its clock; ties go by unit, then slot.
struct Turn {
  double clock;
  uint32_t unit, slot;
  bool operator>(const Turn& o) const {
    return std::tie(clock, unit, slot) > std::tie(o.clock, o.unit, o.slot);
  }
};

class CacheWalk {
 public:
  CacheWalk(const HwConfig& config, BvhView image, LevelReferenceSink* sink, uint32_t tapped)
      : c_(config),
        traversal_(image, without_fetch_list()),
        dram_(config.dram),
        caches_(levels_as_built(config), config.rt_units, dram_, sink, tapped),
        dram_read_(unloaded_dram_read(config.dram, block_bytes(last_level(config).cache))) {
    // A read that reaches level d passes each level's tag check down to d and the links between
    // them, each way.
    double sum = 0;
    for (size_t i = 0; i < c_.memory.size(); ++i) {
      if (i > 0) sum += 2.0 * c_.memory[i - 1].link.latency;
      sum += c_.memory[i].cache.hit_latency;
      reach_.push_back(sum);
    }
    for (uint32_t u = 0; u < c_.rt_units; ++u) {
      units_.emplace_back(c_.rt.warps);
      for (Warp& w : units_.back()) w.lanes.resize(c_.rt.warp_size);
    }
    work_.resize(c_.rt_units);
    mshr_free_.resize(c_.rt_units);
    for (auto& unit : mshr_free_)
      for (uint32_t i = 0; i < first_level(c_).cache.mshrs; ++i) unit.push(0);
  }

  // Steps in the order of the lanes' own clocks (a warp's start plus its ray's latency so far),
  // so a ray whose fetch went to the L2 or DRAM steps again only after the rays that hit in
  // the L1 have taken the steps they fit in that time, as in the cycle model.
  void run(RayStreamReader& reader) {
    for (uint32_t u = 0; u < c_.rt_units; ++u)
      for (uint32_t w = 0; w < c_.rt.warps; ++w) start(u, w, reader);
    while (!turns_.empty()) {
      Turn t = turns_.top();
      turns_.pop();
      uint32_t w = t.slot / c_.rt.warp_size;
      Warp& warp = units_[t.unit][w];
      Lane& lane = warp.lanes[t.slot % c_.rt.warp_size];
      clock_ = t.clock;
      step(t.unit, warp, lane, t.slot);
      if (lane.live) {
        turns_.push({warp.start + lane.latency, t.unit, t.slot});
      } else if (warp.live == 0) {
        shade(t.unit, warp);
        work_[t.unit].warp_cycles += warp.slowest;
        warp.start += warp.slowest;
        warp.slowest = 0;
        start(t.unit, w, reader);
      }
    }
  }

  const std::array<CostTotals, kRayTypeCount>& by_type() const { return by_type_; }
  const std::vector<UnitWork>& work() const { return work_; }
  uint64_t dram_bytes() const { return dram_.bytes; }
  std::vector<CacheStats> level_stats() const {
    std::vector<CacheStats> out;
    for (uint32_t i = 0; i < caches_.levels(); ++i) out.push_back(caches_.stats(i));
    return out;
  }

 private:
  // Fills warp w of the unit with new rays and schedules their first steps.
  void start(uint32_t unit, uint32_t w, RayStreamReader& reader) {
    Warp& warp = units_[unit][w];
    fill(warp, reader);
    for (uint32_t l = 0; l < c_.rt.warp_size; ++l)
      if (warp.lanes[l].live)
        turns_.push({warp.start + warp.lanes[l].latency, unit, w * c_.rt.warp_size + l});
  }

  void fill(Warp& warp, RayStreamReader& reader) {
    for (Lane& lane : warp.lanes) {
      if (!reader.next(lane.ray)) break;
      traversal_.begin(lane.state, lane.ray);
      lane.live = true;
      lane.stack = {};
      lane.latency = c_.rt.setup_latency;
      lane.cost = {};
      warp.live++;
    }
  }

  // One read through the unit's first level; charges `cost` and returns the latency of the data.
  double read(uint32_t unit, CostTotals& cost, uint64_t addr, uint32_t bytes) {
    ReadCharge charge;
    now_ += kReadGap;
    if (caches_.unit(unit).read(addr, bytes, now_, nullptr, 0, charge) == kPending)
      throw std::logic_error("cache level: a cache level did not answer at once");
    cost.reads += charge;
    uint64_t missed = charge.misses(0);
    double first = c_.memory[0].cache.hit_latency;
    if (missed == 0) return first;
    double below_latency = reach_[charge.depth - 1] - first;
    if (charge.dram_bytes > 0) below_latency += dram_read_;
    // Each missed block takes one of the unit's first-level MSHRs after the tag check, waiting
    // for the first to free if all are busy, and holds it until its data is back.
    auto& mshrs = mshr_free_[unit];
    double done = 0;
    for (uint64_t i = 0; i < missed; ++i) {
      double start = std::max(clock_ + first, mshrs.top());
      mshrs.pop();
      mshrs.push(start + below_latency);
      done = std::max(done, start + below_latency);
    }
    return done - clock_;
  }

  // A spill through the unit's first level (posted: nobody waits for it).
  void write(uint32_t unit, uint64_t addr, uint32_t bytes) {
    now_ += kReadGap;
    caches_.unit(unit).write(addr, bytes, now_);
  }

  void step(uint32_t unit, Warp& warp, Lane& lane, uint32_t slot) {
    TraversalState& s = lane.state;
    const StackConfig& stack = c_.rt.stack;
    uint32_t context = unit * c_.rt.warps * c_.rt.warp_size + slot;
    if (lane.stack.refill(1) > 0)  // a step pops one entry
      lane.latency +=
          read(unit, lane.cost,
               HardwareStack::entry_address(context, lane.stack.spilled, stack.entry_bytes),
               stack.entry_bytes);
    auto kept = uint32_t(std::max<size_t>(s.stack.size(), 1) - 1);
    StepResult r = traversal_.step(s);
    if (r.kind == StepKind::Done) {
      retire(warp, lane);
      return;
    }
    UnitWork& w = work_[unit];
    if (r.fetch_bytes > 0) lane.latency += read(unit, lane.cost, r.fetch_address, r.fetch_bytes);
    bool node = r.kind == StepKind::Node, leaf = r.kind == StepKind::Leaf;
    const TestUnitConfig& tests = node ? c_.rt.box : leaf ? c_.rt.triangle : c_.rt.transform;
    uint64_t issues = (std::max<uint32_t>(r.tests, 1) + tests.issue_width - 1) / tests.issue_width;
    (node ? w.box_issues : leaf ? w.triangle_issues : w.transform_issues) += issues;
    lane.latency += tests.latency + double(issues - 1) + c_.rt.control_latency;
    double texels = 0;  // any-hit calls read their texels after the test, all at once
    for (uint64_t addr : s.texels)
      texels = std::max(texels, read(unit, lane.cost, addr, c_.rt.anyhit.read_bytes));
    s.texels.clear();
    lane.latency += texels;
    w.steps++;
    if (uint32_t out = lane.stack.settle(kept, uint32_t(s.stack.size()), stack.entries))
      write(unit,
            HardwareStack::entry_address(context, lane.stack.spilled - out, stack.entry_bytes),
            out * stack.entry_bytes);
  }

  // With the shader model, hit shading reads each hit's bytes through the unit's L1 when the
  // warp's last ray is done, as the cycle model's ShaderCore does (shader_core.h).
  void shade(uint32_t unit, Warp& warp) {
    CostTotals cost;  // no ray's
    for (uint64_t addr : warp.shading) read(unit, cost, addr, c_.shader.bytes_per_hit);
    warp.shading.clear();
  }

  void retire(Warp& warp, Lane& lane) {
    const ShaderConfig& shader = c_.shader;
    if (shader.model != ShaderModel::None && shader.bytes_per_hit > 0 && lane.state.prim != kNoHit)
      warp.shading.push_back(shading_address(lane.ray.frame, lane.ray.pixel, shader.bytes_per_hit));
    lane.live = false;
    warp.live--;
    warp.slowest = std::max(warp.slowest, lane.latency);
    lane.cost.rays = 1;
    lane.cost.nodes = lane.state.counters.trav_nodes;
    lane.cost.triangles = lane.state.counters.trav_prims;
    lane.cost.latency = lane.latency;
    by_type_[int(lane.ray.type) % kRayTypeCount] += lane.cost;
  }

  HwConfig c_;
  TraversalUnit traversal_;
  CountedDram dram_;
  CacheHierarchy caches_;
  double dram_read_;           // DRAM's unloaded read of the last level's block
  std::vector<double> reach_;  // per level: the latency of a read that reaches it
  std::vector<std::vector<Warp>> units_;
  std::vector<UnitWork> work_;
  std::array<CostTotals, kRayTypeCount> by_type_{};
  std::priority_queue<Turn, std::vector<Turn>, std::greater<Turn>> turns_;
  // Per unit: the clocks its L1 MSHRs are free from, earliest first.
  std::vector<std::priority_queue<double, std::vector<double>, std::greater<double>>> mshr_free_;
  double clock_ = 0;  // the clock of the step being taken
  Cycle now_ = 0;
};

}  // namespace

FidelityResult run_cache_level(const HwConfig& config, BvhView image, const std::string& stream,
                               const CacheLevelTaps& taps) {
  HostTimer timer;
  RayStreamReader reader(stream);
  HwConfig analysed = config;  // a banked DRAM as its bandwidth and unloaded latency
  analysed.dram = dram_for_analysis(config);
  CacheWalk walk(analysed, image, taps.sink, taps.tapped);
  walk.run(reader);
  FidelityResult result;
  result.level = FidelityLevel::CacheLevel;
  result.clock_ghz = config.clock_ghz;
  set_exact_estimates(result, walk.by_type(), level_names(config.memory), true);
  result.simulated_rays = result.rays;
  double latency = 0;
  for (const CostTotals& t : walk.by_type()) latency += t.latency;
  AnalyticInputs inputs{walk.work(), result.rays, walk.dram_bytes(),
                        latency / double(std::max<uint64_t>(result.rays, 1))};
  AnalyticTime time = analytic_time(analysed, inputs);
  result.cycles = Estimate::exact(time.cycles);
  result.time_model = "roofline, bound by " + time.bound;
  if (taps.bounds) *taps.bounds = time;
  if (taps.levels) *taps.levels = walk.level_stats();
  timer.stop(result);
  return result;
}

}  // namespace rtsim
