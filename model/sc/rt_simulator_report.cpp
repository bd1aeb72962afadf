// RtSimulator::report: every module's counters under dotted names, and the ratios derived
// from them (declared here once, computed when written).
#include <string>

#include "model/sc/rt_simulator.h"

namespace rtsim {
namespace {

// port_peak: bytes per cycle of all the level's data ports together (0: no limit).
void report_cache(StatsRegistry& r, const std::string& p, const CacheStats& s, bool cold,
                  double port_peak) {
  r.counter(p + ".accesses", s.accesses);
  r.counter(p + ".hits", s.hits);
  r.counter(p + ".misses", s.misses);
  if (cold) {
    r.counter(p + ".cold_misses", s.cold_misses);
    r.ratio(p + ".compulsory_share", p + ".cold_misses", p + ".misses");
  }
  r.counter(p + ".mshr_merges", s.mshr_merges);
  r.counter(p + ".merge_limit_stalls", s.merge_limit_stalls);
  r.counter(p + ".mshr_stall_cycles", s.mshr_stall_cycles);
  r.counter(p + ".bank_conflicts", s.bank_conflicts);
  r.counter(p + ".bank_stall_cycles", s.bank_stall_cycles);
  r.counter(p + ".port_stall_cycles", s.port_stall_cycles);
  if (port_peak > 0) {
    r.counter(p + ".port_bytes", s.bytes_read + s.write_bytes);
    r.ratio(p + ".port_utilisation", p + ".port_bytes", "cycles", 1.0 / port_peak);
  }
  r.counter(p + ".evictions", s.evictions);
  r.counter(p + ".bytes_read", s.bytes_read);
  r.counter(p + ".bytes_below", s.bytes_below);
  r.counter(p + ".writes", s.writes);
  r.counter(p + ".write_misses", s.write_misses);
  r.counter(p + ".write_bytes", s.write_bytes);
  r.counter(p + ".writebacks", s.writebacks);
  r.counter(p + ".writeback_bytes", s.writeback_bytes);
  r.counter(p + ".local_reads", s.local_reads);
  r.counter(p + ".local_misses", s.local_misses);
  r.counter(p + ".victims", s.victims);
  r.counter(p + ".victim_fills", s.victim_fills);
  r.ratio(p + ".hit_rate", p + ".hits", p + ".accesses");
  r.counter(p + ".served", s.hits + s.mshr_merges);
  r.ratio(p + ".served_rate", p + ".served", p + ".accesses");
}

void report_link(StatsRegistry& r, const std::string& p, const Link& link, double peak) {
  const LinkStats& s = link.stats();
  r.counter(p + ".transfers", s.transfers);
  r.counter(p + ".bytes", s.bytes);
  r.counter(p + ".stall_cycles", s.stall_cycles);
  if (peak > 0) r.ratio(p + ".utilisation", p + ".bytes", "cycles", 1.0 / peak);
}

// The crossbar in front of an instance's slices: each slice's links, and each requester's
// (a unit, or an instance of the level above).
void report_crossbar(StatsRegistry& r, const std::string& p, const Crossbar& xbar,
                     const std::vector<std::string>& requesters) {
  if (!xbar.modelled()) return;
  double peak = xbar.config().bytes_per_cycle;
  for (uint32_t i = 0; i < xbar.slices(); ++i) {
    std::string q = p + ".xbar.slice" + std::to_string(i);
    report_link(r, q + ".in", xbar.slice_in(i), peak);
    report_link(r, q + ".out", xbar.slice_out(i), peak);
  }
  for (uint32_t i = 0; i < xbar.units(); ++i) {
    std::string q =
        p + ".xbar." + (i < requesters.size() ? requesters[i] : "tlm" + std::to_string(i));
    report_link(r, q + ".up", xbar.unit_up(i), peak);
    report_link(r, q + ".down", xbar.unit_down(i), peak);
  }
}

// A level several units share: its instances summed (mem.NAME), each instance of a group level
// (mem.NAME.gK), each slice, and the crossbar in front of each instance.
void report_shared_level(StatsRegistry& r, const SharedLevelsModule& shared, uint32_t level,
                         uint32_t units) {
  const MemoryLevelConfig& config = shared.levels()[level];
  auto [begin, end] = shared.instances_of(level);
  CacheStats sum;
  for (uint32_t i = begin; i < end; ++i) sum += shared.instances()[i].stats();
  const std::string p = "mem." + config.name;
  uint32_t slices = (end - begin) * config.slices;
  report_cache(r, p, sum, shared.tracks_cold_misses(), config.cache.bytes_per_cycle * slices);
  for (uint32_t i = begin; i < end; ++i) {
    const SharedLevelsModule::Instance& inst = shared.instances()[i];
    const std::string q = "mem." + inst.name;
    if (end - begin > 1)
      report_cache(r, q, inst.stats(), shared.tracks_cold_misses(),
                   config.cache.bytes_per_cycle * config.slices);
    if (inst.slices.size() > 1)
      for (uint32_t k = 0; k < inst.slices.size(); ++k) {
        const CacheStats& st = inst.slices[k]->stats();
        std::string sp = q + ".slice" + std::to_string(k);
        r.counter(sp + ".accesses", st.accesses);
        r.counter(sp + ".misses", st.misses);
        r.counter(sp + ".bank_stall_cycles", st.bank_stall_cycles);
        r.counter(sp + ".port_stall_cycles", st.port_stall_cycles);
        r.counter(sp + ".mshr_stall_cycles", st.mshr_stall_cycles);
      }
    std::vector<std::string> requesters;
    if (begin == 0) {  // the first shared level: its requesters are units, in unit order
      for (uint32_t u = 0; u < units; ++u)
        if (shared.entry(u) == i) requesters.push_back("rt" + std::to_string(u));
    } else {
      for (const auto& above : shared.instances())
        if (above.below == i) requesters.push_back(above.name);
    }
    report_crossbar(r, q, inst.crossbar, requesters);
  }
}

// Every cache level under mem.NAME: a unit's own level summed over the units and per unit
// (mem.NAME.rtK), a shared one by report_shared_level.
void report_memory(StatsRegistry& r, const std::vector<std::unique_ptr<RtUnitModule>>& units,
                   const SharedLevelsModule& shared) {
  const std::vector<MemoryLevelConfig>& levels = shared.levels();
  for (uint32_t i = 0; i < levels.size(); ++i) {
    if (queued_level(levels[i])) {
      report_shared_level(r, shared, i, uint32_t(units.size()));
      continue;
    }
    const std::string p = "mem." + levels[i].name;
    double peak = levels[i].cache.bytes_per_cycle;
    CacheStats sum;
    for (const auto& unit : units) sum += unit->memory.level(i).stats();
    report_cache(r, p, sum, true, peak * double(units.size()));
    for (const auto& unit : units)
      report_cache(r, p + ".rt" + std::to_string(unit->core().id()), unit->memory.level(i).stats(),
                   true, peak);
  }
}

// The banked DRAM: the simple model's names where they mean the same (dram.bytes,
// dram.utilisation: data buses busy, mean over channels), and its own: row buffer outcomes per
// burst, commands (for an energy model), turnarounds, refresh, queue occupancy, read latency
// percentiles (gauges: over the whole run, warm-up included) and per-channel and per-bank
// data bus utilisation.
void report_banked_dram(StatsRegistry& r, const DramController& dram, double core_ghz) {
  const BankedDramStats& s = dram.stats();
  const BankedDramConfig& c = dram.config();
  double core_per_clock = core_ghz * 1000 / c.clock_mhz;
  r.counter("dram.requests", s.reads + s.writes);
  r.counter("dram.reads", s.reads);
  r.counter("dram.writes", s.writes);
  r.counter("dram.bytes", s.read_bytes + s.write_bytes);
  r.counter("dram.write_bytes", s.write_bytes);
  double busy = 0;
  for (uint32_t ch = 0; ch < dram.channels(); ++ch) busy += double(dram.channel(ch).data_busy());
  r.real("dram.busy_cycles", busy / dram.channels() * core_per_clock);
  r.counter("dram.total_latency_cycles", s.read_latency.sum());
  r.ratio("dram.utilisation", "dram.busy_cycles", "cycles");
  r.ratio("dram.bytes_per_cycle", "dram.bytes", "cycles");
  r.ratio("dram.bytes_per_ray", "dram.bytes", "rays");
  r.ratio("dram.mean_latency", "dram.total_latency_cycles", "dram.reads");
  r.gauge("dram.latency_p50", s.read_latency.percentile(0.50));
  r.gauge("dram.latency_p90", s.read_latency.percentile(0.90));
  r.gauge("dram.latency_p99", s.read_latency.percentile(0.99));
  r.gauge("dram.latency_max", s.read_latency.max());
  r.counter("dram.row_hits", s.row_hits);
  r.counter("dram.row_misses", s.row_misses);
  r.counter("dram.row_conflicts", s.row_conflicts);
  r.counter("dram.cmd.act", s.commands.act);
  r.counter("dram.cmd.pre", s.commands.pre);
  r.counter("dram.cmd.rd", s.commands.rd);
  r.counter("dram.cmd.wr", s.commands.wr);
  r.counter("dram.cmd.ref", s.commands.ref);
  r.counter("dram.cmd.ref_pb", s.commands.ref_pb);
  r.counter("dram.bursts", s.commands.rd + s.commands.wr);
  r.ratio("dram.row_hit_rate", "dram.row_hits", "dram.bursts");
  r.ratio("dram.row_conflict_rate", "dram.row_conflicts", "dram.bursts");
  r.counter("dram.turnarounds", s.turnarounds);
  r.counter("dram.refresh_stall_clocks", s.refresh_stall_clocks);
  r.real("dram.queued_burst_clocks", s.queued_burst_clocks);
  for (uint32_t ch = 0; ch < dram.channels(); ++ch) {
    const std::string p = "dram.ch" + std::to_string(ch);
    const DramChannel& channel = dram.channel(ch);
    r.counter(p + ".busy_clocks", channel.data_busy());
    r.ratio(p + ".utilisation", p + ".busy_clocks", "cycles", core_per_clock);
    for (size_t b = 0; b < channel.bank_busy().size(); ++b) {
      const std::string q = p + ".bank" + std::to_string(b);
      r.counter(q + ".busy_clocks", channel.bank_busy()[b]);
      r.ratio(q + ".utilisation", q + ".busy_clocks", "cycles", core_per_clock);
    }
  }
  r.ratio("dram.queue_occupancy", "dram.queued_burst_clocks", "cycles",
          core_per_clock / c.channels);
}

void report_test_units(StatsRegistry& r, const std::string& p, const TestUnitPool& pool) {
  const TestUnitStats& s = pool.stats();
  r.counter(p + ".requests", s.requests);
  r.counter(p + ".tests", s.tests);
  r.counter(p + ".issues", s.issues);
  r.counter(p + ".stall_cycles", s.stall_cycles);
  r.counter(p + ".calendar_conflicts", s.calendar_conflicts);
  r.ratio(p + ".utilisation", p + ".issues", "cycles", 1.0 / pool.config().count);
}

// What one kind of read cost: accesses, misses and the miss rate at each cache level
// (p.mem.NAME.*), DRAM bytes read.
void report_read_counts(StatsRegistry& r, const std::string& p, const ReadCounts& sum,
                        const std::vector<MemoryLevelConfig>& levels) {
  for (uint32_t i = 0; i < levels.size(); ++i) {
    const std::string q = p + ".mem." + levels[i].name;
    r.counter(q + ".accesses", sum.accesses[i]);
    r.counter(q + ".misses", sum.misses(i));
    r.ratio(q + ".miss_rate", q + ".misses", q + ".accesses");
  }
  r.counter(p + ".dram_read_bytes", sum.dram_bytes);
}

// report_read_counts of one kind of the units' reads, summed over the units.
void report_reads(StatsRegistry& r, const std::string& p,
                  const std::vector<std::unique_ptr<RtUnitModule>>& units,
                  ReadCounts RtCoreStats::*kind, const std::vector<MemoryLevelConfig>& levels) {
  ReadCounts sum;
  for (const auto& unit : units) sum += unit->core().stats().*kind;
  report_read_counts(r, p, sum, levels);
}

// The shader side (model/sched/shader_core.h): each SM's scheduler time by shader, and the
// totals; warp slots the units waited for; what the shading reads cost.
void report_shader(StatsRegistry& r, const std::vector<std::unique_ptr<RtUnitModule>>& units,
                   uint32_t schedulers, const std::vector<MemoryLevelConfig>& levels) {
  ShaderStats sum;
  for (const auto& unit : units) {
    if (!unit->shader()) continue;  // before the simulation starts
    const ShaderStats& s = unit->shader()->stats();
    const std::string p = "rt" + std::to_string(unit->core().id()) + ".shader";
    r.counter(p + ".busy_cycles", s.busy_cycles());
    r.ratio(p + ".utilisation", p + ".busy_cycles", "cycles", 1.0 / schedulers);
    sum += s;
  }
  ReadCounts reads;
  for (const ReadCounts& c : sum.reads) reads += c;
  r.counter("shader.warps", sum.warps);
  r.counter("shader.rays", sum.rays);
  r.counter("shader.hits", sum.hits);
  r.counter("shader.raygen_cycles", sum.raygen_cycles);
  r.counter("shader.hit_cycles", sum.hit_cycles);
  r.counter("shader.miss_cycles", sum.miss_cycles);
  r.counter("shader.busy_cycles", sum.busy_cycles());
  for (int t = 0; t < kRayTypeCount; ++t)
    if (sum.type_cycles[t] > 0)
      r.counter(std::string("shader.type.") + ray_type_name(RayType(t)) + ".busy_cycles",
                sum.type_cycles[t]);
  r.counter("shader.trace_delay_cycles", sum.trace_delay_cycles);
  r.counter("shader.slot_waits", sum.slot_waits);
  r.counter("shader.slot_wait_cycles", sum.slot_wait_cycles);
  r.counter("shader.read_bytes", sum.read_bytes);
  report_read_counts(r, "shader.reads", reads, levels);
  r.ratio("shader.utilisation", "shader.busy_cycles", "cycles",
          1.0 / (double(schedulers) * double(units.size())));
  r.ratio("shader.busy_cycles_per_ray", "shader.busy_cycles", "rays");
  r.ratio("shader.mean_trace_delay", "shader.trace_delay_cycles", "shader.rays");
  r.ratio("shader.reads.dram_bytes_per_ray", "shader.reads.dram_read_bytes", "rays");
}

// Two levels: steps and reads of each level, over the units, and per ray.
void report_levels(StatsRegistry& r, const std::vector<std::unique_ptr<RtUnitModule>>& units,
                   const std::vector<MemoryLevelConfig>& levels) {
  uint64_t instances = 0, top_nodes = 0, nodes = 0;
  for (const auto& unit : units) {
    const RtCoreStats& s = unit->core().stats();
    instances += s.instance_steps;
    top_nodes += s.top_node_steps;
    nodes += s.node_steps;
  }
  r.counter("bvh.instance_steps", instances);
  r.counter("bvh.top.node_steps", top_nodes);
  r.counter("bvh.bottom.node_steps", nodes - top_nodes);
  r.ratio("bvh.instances_per_ray", "bvh.instance_steps", "rays");
  for (const char* level : {"top", "bottom"}) {
    std::string p = std::string("bvh.") + level;
    report_reads(r, p, units, level[0] == 't' ? &RtCoreStats::top : &RtCoreStats::bottom, levels);
    r.ratio(p + ".nodes_per_ray", p + ".node_steps", "rays");
    r.ratio(p + ".dram_bytes_per_ray", p + ".dram_read_bytes", "rays");
  }
}

// Alpha-tested scenes: the any-hit calls, the cycles rays waited for them, and what the
// shader's texel reads cost.
void report_anyhit(StatsRegistry& r, const std::vector<std::unique_ptr<RtUnitModule>>& units,
                   const std::vector<MemoryLevelConfig>& levels) {
  uint64_t calls = 0, cycles = 0;
  for (const auto& unit : units) {
    calls += unit->core().stats().anyhit_calls;
    cycles += unit->core().stats().anyhit_cycles;
  }
  r.counter("anyhit.calls", calls);
  r.counter("anyhit.wait_cycles", cycles);
  report_reads(r, "anyhit.texture", units, &RtCoreStats::texture, levels);
  r.ratio("anyhit.calls_per_ray", "anyhit.calls", "rays");
  r.ratio("anyhit.mean_wait", "anyhit.wait_cycles", "anyhit.calls");
  r.ratio("anyhit.texture.dram_bytes_per_ray", "anyhit.texture.dram_read_bytes", "rays");
}

// The ray buffer's SRAM, and the states kept in memory: what the units read and wrote through
// their L1s, and what those reads cost below.
void report_ray_buffer(StatsRegistry& r, const RayBuffer& buffer,
                       const std::vector<std::unique_ptr<RtUnitModule>>& units,
                       const std::vector<MemoryLevelConfig>& levels) {
  const RayBufferStats& b = buffer.stats();
  const std::string p = "treelet_queues.buffer";
  r.gauge(p + ".state_bytes", buffer.state_bytes());
  r.gauge(p + ".capacity", buffer.capacity());
  r.gauge(p + ".max_in_sram", b.max_in_sram);
  r.counter(p + ".sram_writes", b.sram_writes);
  r.counter(p + ".sram_reads", b.sram_reads);
  r.counter(p + ".sram_bytes", b.sram_bytes);
  r.counter(p + ".port_cycles", b.port_cycles);
  r.counter(p + ".port_waits", b.port_waits);
  r.counter(p + ".held", b.held);
  r.counter(p + ".refused", b.refused);
  r.counter(p + ".memory_writes", b.memory_writes);
  r.counter(p + ".memory_reads", b.memory_reads);
  r.counter(p + ".memory_bytes", b.memory_bytes);
  report_reads(r, p, units, &RtCoreStats::state, levels);
  r.ratio(p + ".sram_bytes_per_ray", p + ".sram_bytes", "rays");
  r.ratio(p + ".memory_bytes_per_ray", p + ".memory_bytes", "rays");
}

// Treelet prefetching, over the units: what the prefetchers asked for and what their L1s made
// of it.
void report_prefetch(StatsRegistry& r, const std::vector<std::unique_ptr<RtUnitModule>>& units) {
  uint64_t treelets = 0, bytes = 0, skipped = 0;
  CacheStats l1;
  for (const auto& unit : units) {
    const PrefetchStats& s = unit->core().prefetch_stats();
    treelets += s.treelets;
    bytes += s.bytes;
    skipped += s.skipped;
    l1 += unit->memory.cache().stats();
  }
  const std::string p = "rt.prefetch";
  r.counter(p + ".treelets", treelets);
  r.counter(p + ".bytes", bytes);
  r.counter(p + ".skipped", skipped);
  r.counter(p + ".blocks", l1.prefetches);
  r.counter(p + ".redundant", l1.prefetch_redundant);
  r.counter(p + ".useful", l1.prefetch_useful);
  r.counter(p + ".late", l1.prefetch_late);
  r.counter(p + ".useless", l1.prefetch_useless);
  // Demand misses of BVH data: stack refills and ray states (local memory) are no treelet's.
  r.counter(p + ".needed", l1.prefetch_useful + l1.misses - l1.local_misses);
  r.ratio(p + ".accuracy", p + ".useful", p + ".blocks");
  r.ratio(p + ".coverage", p + ".useful", p + ".needed");
}

// Counters every unit has, summed over the units as "rt.*" too.
struct UnitTotals {
  uint64_t steps = 0, warp_steps = 0, active_lanes = 0, node_warp_steps = 0, distinct_nodes = 0;
  uint64_t packet_lanes = 0, reorders = 0;
  uint64_t spill_entries = 0, refill_entries = 0, postponed = 0, refused = 0;
  double ray_slot_cycles = 0;
};

}  // namespace

void RtSimulator::report(StatsRegistry& r) const {
  report_all(r, cycles());
  if (warmup()) r.subtract(before_measuring_);
}

void RtSimulator::report_all(StatsRegistry& r, Cycle end) const {
  r.counter("cycles", end);
  r.counter("rays", collector_.rays());
  r.ratio("rays_per_cycle", "rays", "cycles");
  r.ratio("mrays_per_second", "rays", "cycles", config_.clock_ghz * 1e3);

  const DispatchStats& d = dispatch_->dispatcher().stats();
  r.counter("dispatch.rays", d.rays);
  r.counter("dispatch.takes", d.takes);
  r.real("dispatch.busy_cycles", d.busy_cycles);
  r.counter("dispatch.wait_cycles", d.wait_cycles);
  r.counter("dispatch.pool_empty", d.pool_empty);
  r.ratio("dispatch.utilisation", "dispatch.busy_cycles", "cycles");

  if (treelets_) {
    const TreeletQueueStats& t = treelets_->scheduler().stats();
    const std::string p = "treelet_queues";
    r.counter(p + ".visits", t.visits);
    r.counter(p + ".visit_rays", t.visit_rays);
    r.counter(p + ".fresh_visits", t.fresh_visits);
    r.counter(p + ".postponed", t.postponed);
    r.counter(p + ".refused", t.refused);
    r.gauge(p + ".max_queued", t.max_queued);
    r.gauge(p + ".max_queue_length", t.max_queue_length);
    r.real(p + ".queued_ray_cycles", t.queued_ray_cycles);
    r.ratio(p + ".rays_per_visit", p + ".visit_rays", p + ".visits");
    r.ratio(p + ".mean_queued", p + ".queued_ray_cycles", "cycles");
    r.ratio(p + ".occupancy", p + ".queued_ray_cycles", "cycles",
            1.0 / config_.treelet_queues.max_rays);
    report_ray_buffer(r, treelets_->scheduler().buffer(), units_, config_.memory);
  }

  if (sorter_) {
    const SortStats& s = sorter_->sorter().stats();
    r.counter("sort.rays", s.rays);
    r.counter("sort.takes", s.takes);
    r.counter("sort.bins_served", s.bins_served);
    r.counter("sort.aged", s.aged);
    r.counter("sort.wait_cycles", s.wait_cycles);
    r.gauge("sort.max_held", s.max_held);
    r.ratio("sort.bins_per_take", "sort.bins_served", "sort.takes");
    r.ratio("sort.mean_wait", "sort.wait_cycles", "sort.rays");
  }

  bool two_level = traversal_.bvh().two_level();
  bool alpha_tested = traversal_.bvh().alpha_tested();
  UnitTotals total;
  uint32_t slots = config_.rt.warps * config_.rt.warp_size;
  for (const auto& unit : units_) {
    const RtCore& core = unit->core();
    const RtCoreStats& s = core.stats();
    const std::string p = "rt" + std::to_string(core.id());
    uint64_t steps = s.node_steps + s.leaf_steps + s.instance_steps;
    r.counter(p + ".rays", s.rays_retired);
    r.counter(p + ".node_steps", s.node_steps);
    r.counter(p + ".leaf_steps", s.leaf_steps);
    r.counter(p + ".issue_stalls", s.issue_stalls);
    r.counter(p + ".fetches", s.fetches);
    r.counter(p + ".fetch_bytes", s.fetch_bytes);
    r.counter(p + ".waited_reads", s.waited_reads);
    r.counter(p + ".late_data", s.late_data);
    r.counter(p + ".late_cycles", s.late_cycles);
    r.counter(p + ".stack.spill_writes", s.spill_writes);
    r.counter(p + ".stack.spill_entries", s.spill_entries);
    r.counter(p + ".stack.refill_reads", s.refill_reads);
    r.counter(p + ".stack.refill_entries", s.refill_entries);
    r.real(p + ".ray_slot_cycles", s.ray_slot_cycles);
    r.ratio(p + ".slot_occupancy", p + ".ray_slot_cycles", "cycles", 1.0 / slots);
    r.counter(p + ".control.issues", s.issues);
    r.ratio(p + ".control.utilisation", p + ".control.issues", "cycles",
            1.0 / config_.rt.issue_per_cycle);
    report_test_units(r, p + ".box", core.box());
    report_test_units(r, p + ".triangle", core.triangle());
    if (two_level) {
      r.counter(p + ".instance_steps", s.instance_steps);
      report_test_units(r, p + ".transform", core.transform());
    }
    if (alpha_tested) report_test_units(r, p + ".anyhit", core.anyhit_shader());
    total.steps += steps;
    total.warp_steps += s.warp_steps;
    total.active_lanes += s.active_lanes;
    total.packet_lanes += s.packet_lanes;
    total.reorders += s.reorders;
    total.node_warp_steps += s.node_warp_steps;
    total.distinct_nodes += s.distinct_nodes;
    total.spill_entries += s.spill_entries;
    total.refill_entries += s.refill_entries;
    total.postponed += s.postponed;
    total.refused += s.refused;
    total.ray_slot_cycles += s.ray_slot_cycles;
  }
  r.counter("rt.steps", total.steps);
  r.counter("rt.warp_steps", total.warp_steps);
  r.counter("rt.active_lanes", total.active_lanes);
  r.counter("rt.packet_lanes", total.packet_lanes);
  r.counter("rt.packet_reorders", total.reorders);
  r.counter("rt.node_warp_steps", total.node_warp_steps);
  r.counter("rt.distinct_nodes", total.distinct_nodes);
  r.counter("rt.stack.spill_entries", total.spill_entries);
  r.counter("rt.stack.refill_entries", total.refill_entries);
  r.counter("rt.postponed", total.postponed);
  r.counter("rt.postpones_refused", total.refused);
  r.real("rt.ray_slot_cycles", total.ray_slot_cycles);
  r.ratio("rt.simd_efficiency", "rt.active_lanes", "rt.packet_lanes");
  r.ratio("rt.distinct_nodes_per_warp_step", "rt.distinct_nodes", "rt.node_warp_steps");
  r.ratio("rt.slot_occupancy", "rt.ray_slot_cycles", "cycles",
          1.0 / (double(slots) * config_.rt_units));

  if (two_level) report_levels(r, units_, config_.memory);
  if (alpha_tested) report_anyhit(r, units_, config_.memory);
  if (config_.shader.model != ShaderModel::None)
    report_shader(r, units_, config_.shader.schedulers, config_.memory);
  if (config_.rt.prefetch.trigger != PrefetchTrigger::None) report_prefetch(r, units_);
  report_memory(r, units_, *shared_);
  if (banked_dram_) report_banked_dram(r, banked_dram_->controller(), config_.clock_ghz);
  if (dram_) {
    const DramStats& s = dram_->dram().stats();
    r.counter("dram.requests", s.requests);
    r.counter("dram.bytes", s.bytes);
    r.counter("dram.write_bytes", s.write_bytes);
    r.real("dram.busy_cycles", s.busy_cycles);
    r.counter("dram.queue_stall_cycles", s.queue_stall_cycles);
    r.counter("dram.total_latency_cycles", s.total_latency_cycles);
    r.ratio("dram.utilisation", "dram.busy_cycles", "cycles");
    r.ratio("dram.bytes_per_cycle", "dram.bytes", "cycles");
    r.ratio("dram.bytes_per_ray", "dram.bytes", "rays");
    r.ratio("dram.mean_latency", "dram.total_latency_cycles", "dram.requests");
  }

  for (int t = 0; t < kRayTypeCount; ++t) {
    const RayTypeStats& s = collector_.by_type()[t];
    if (s.rays == 0) continue;
    const std::string p = std::string("type.") + ray_type_name(RayType(t));
    r.counter(p + ".rays", s.rays);
    r.counter(p + ".hits", s.hits);
    r.counter(p + ".trav_nodes", s.counters.trav_nodes);
    r.counter(p + ".trav_leaves", s.counters.trav_leaves);
    r.counter(p + ".trav_prims", s.counters.trav_prims);
    r.counter(p + ".trav_prim_hits", s.counters.trav_prim_hits);
    if (alpha_tested) {
      r.counter(p + ".trav_alpha_tests", s.counters.trav_alpha_tests);
      r.counter(p + ".anyhit_cycles", s.anyhit_cycles);
      r.ratio(p + ".anyhit_calls_per_ray", p + ".trav_alpha_tests", p + ".rays");
    }
    if (two_level) {
      r.counter(p + ".trav_instances", s.counters.trav_instances);
      r.ratio(p + ".instances_per_ray", p + ".trav_instances", p + ".rays");
    }
    for (uint32_t i = 0; i < config_.memory.size(); ++i) {
      const std::string q = p + ".mem." + config_.memory[i].name;
      r.counter(q + ".accesses", s.reads.accesses[i]);
      r.counter(q + ".hits", s.reads.hits[i]);
      r.ratio(q + ".hit_rate", q + ".hits", q + ".accesses");
    }
    r.counter(p + ".dram_bytes", s.reads.dram_bytes);
    r.counter(p + ".stack_spills", s.stack_spills);
    r.counter(p + ".stack_refills", s.stack_refills);
    r.counter(p + ".postponed", s.postponed);
    r.ratio(p + ".nodes_per_ray", p + ".trav_nodes", p + ".rays");
    r.ratio(p + ".triangles_per_ray", p + ".trav_prims", p + ".rays");
    r.ratio(p + ".dram_bytes_per_ray", p + ".dram_bytes", p + ".rays");
    r.ratio(p + ".stack_spills_per_ray", p + ".stack_spills", p + ".rays");
  }
}

}  // namespace rtsim
