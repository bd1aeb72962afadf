// The latency ladder: one ray alone on a one-triangle scene, its two reads served by each cache
// level in turn, and one read at a time to a closed, open and conflicting DRAM row, each against
// the sum of the configured latencies (model/VALIDATION.md).
#include <cmath>
#include <optional>
#include <set>

#include <fmt/core.h>

#include "model/mem/dram_address.h"
#include "model/mem/dram_controller.h"
#include "reports/validate/checks.h"
#include "reports/validate/sim_runs.h"

namespace rtsim::validation {
namespace {

// A root node with one child and a leaf with one triangle in front of the ray.
struct OneTriangle {
  explicit OneTriangle(const BvhConfig& bvh) {
    mesh.positions = {{-1, -1, 5}, {1, -1, 5}, {0, 1, 5}};
    mesh.triangles = {{0, 1, 2}};
    image = build_bvh_image(mesh, bvh);
    rays.assign(2, Ray{});
  }
  TriangleMesh mesh;
  BvhImage image;
  std::vector<Ray> rays;  // the same ray twice: the first warms the caches up
};

// Cycles of a read that hits level k: each level's tag check down to it, and each link crossed
// both ways (model/SIM.md, "The memory hierarchy").
double hit_cycles(const std::vector<MemoryLevelConfig>& levels, uint32_t k) {
  double cycles = 0;
  for (uint32_t i = 0; i <= k; ++i) cycles += levels[i].cache.hit_latency;
  for (uint32_t i = 0; i < k; ++i) cycles += 2.0 * levels[i].link.latency;
  return cycles;
}

// Distinct lines of `line_bytes` that the ray's two reads (the root node, the leaf's record)
// touch.
uint32_t lines_read(const BvhImage& image, uint32_t line_bytes) {
  std::set<uint64_t> lines;
  for (auto [addr, bytes] : {std::pair<uint64_t, uint64_t>{image.node_address(0), image.node_size},
                             {image.triangle_address(0), image.triangle_stride}})
    for (uint64_t line = addr / line_bytes; line <= (addr + bytes - 1) / line_bytes; ++line)
      lines.insert(line);
  return uint32_t(lines.size());
}

// The two-unit machine on which the second ray's reads hit level k (k >= 1): every level above
// it private to a unit (a group level becomes one per unit: only latencies count here), level k
// and below shared by both. For a victim level, the level above is one set of one way fewer
// than the lines the ray reads: each line the first ray reads pushes out the one read longest
// ago, whose data is in by then (a line evicted while its fetch is in flight never reaches the
// victim level), and each of the second ray's misses there pushes out the line it reads next.
// Empty, with why, when no machine does that.
std::optional<HwConfig> rung_machine(const HwConfig& one_unit, const BvhImage& image, uint32_t k,
                                     std::string& why) {
  HwConfig c = one_unit;
  c.rt_units = 2;
  c.dispatch.rays_per_cycle = 1.0 / 4096;
  std::vector<MemoryLevelConfig>& levels = c.memory;
  bool victim = levels[k].fill == LevelFill::Victim;
  uint32_t fresh = victim ? k - 1 : k;  // the first level both rays' units share
  for (uint32_t i = 0; i < levels.size(); ++i) {
    MemoryLevelConfig& l = levels[i];
    if (i < fresh && l.scope == LevelScope::Shared) {
      why = fmt::format("memory.{} is shared: the second ray finds the line there", l.name);
      return std::nullopt;
    }
    if (i >= fresh && l.scope == LevelScope::Unit) {
      why = fmt::format("memory.{} is each unit's own: no other unit's ray reaches it", l.name);
      return std::nullopt;
    }
    if (l.scope == LevelScope::Group) {
      l.scope = i < fresh ? LevelScope::Group : LevelScope::Shared;
      l.group = 1;
    }
  }
  if (victim) {
    CacheConfig& above = levels[k - 1].cache;
    uint32_t lines = lines_read(image, above.line_bytes);
    if (lines < 2) {
      why = "the ray's reads touch one line: nothing leaves the level above for the victim level";
      return std::nullopt;
    }
    above.ways = lines - 1;
    above.size_bytes = uint64_t(above.line_bytes) * above.ways;
    levels[k - 1].slices = 1;
  }
  return c;
}

std::vector<Check> ray_ladder(const Target& target) {
  const HwConfig& preset = target.config;
  const std::vector<MemoryLevelConfig>& levels = preset.memory;
  OneTriangle scene(preset.bvh);
  HwConfig one = unloaded(preset);
  one.rt_units = 1;
  one.rt.warps = 1;
  one.rt.warp_size = 1;
  one.sim.warmup_rays = 1;
  const RtCoreConfig& rt = preset.rt;
  double fixed = preset.dispatch.latency + rt.setup_latency + rt.box.latency + rt.triangle.latency +
                 2.0 * rt.control_latency;
  std::string terms = fmt::format(
      "dispatch.latency {} + rt.setup_latency {} + rt.box.latency {} + rt.triangle.latency {} + "
      "2 x rt.control_latency {}",
      preset.dispatch.latency, rt.setup_latency, rt.box.latency, rt.triangle.latency,
      rt.control_latency);
  std::vector<Check> out;
  std::vector<SimJob> jobs;
  for (uint32_t k = 0; k < levels.size(); ++k) {
    const MemoryLevelConfig& level = levels[k];
    Check c{"ladder." + level.name + "_hit", "closed_form",
            k == 0
                ? fmt::format("one ray, both reads hit the unit's {}", level.name)
                : fmt::format("one ray, both reads miss the levels above and hit {}", level.name)};
    std::string sum;
    for (uint32_t i = 0; i <= k; ++i)
      sum += fmt::format("{}memory.{}.hit_latency {}", i ? " + " : "", levels[i].name,
                         levels[i].cache.hit_latency);
    for (uint32_t i = 0; i < k; ++i)
      sum +=
          fmt::format(" + 2 x memory.{}.link_latency {}", levels[i].name, levels[i].link.latency);
    c.source = fmt::format("formula: {} + 2 reads x ({})", terms, sum);
    c.unit = "cycles";
    set_exact(c, fixed + 2 * hit_cycles(levels, k));
    c.look_at = k == 0 ? "RtCore::on_ray, test_step, Cache::read (model/sched, model/mem)"
                       : "the miss path: UnitMemory, Crossbar, SharedLevelsModule (model/sc, "
                         "model/mem)";
    std::string why;
    std::optional<HwConfig> machine = k == 0 ? one : rung_machine(one, scene.image, k, why);
    if (!machine) {
      c.skipped = why;
    } else {
      c.detail = k == 0 ? "1 unit, 1 ray slot, bandwidth limits off; the same ray twice, the "
                          "first as warm-up; cycles from the second ray's dispatch to its "
                          "retirement"
                        : "2 units, 1 ray slot each, one ray dispatched every 4096 cycles: the "
                          "second ray runs on the other unit after the first left its lines "
                          "below (group levels taken per unit above this level, shared from it "
                          "on; a victim level's upper level one set of a way fewer than the lines "
                          "read)";
      jobs.push_back({*machine, &scene.image, &scene.rays});
    }
    out.push_back(c);
  }
  std::vector<SimFigures> runs = simulate(target, jobs);
  size_t run = 0;
  for (Check& c : out)
    if (c.ran()) c.measured = runs[run++]["cycles"];
  return out;
}

// One read at a time to the banked DRAM's controller, refresh off.
class DramProbe {
 public:
  // Expects what `preset` configures, of a controller built as `run` configures it.
  DramProbe(const HwConfig& preset, const HwConfig& run, uint32_t line)
      : config_(without_refresh(preset.banked_dram)),
        controller_(without_refresh(run.banked_dram), run.clock_ghz),
        map_(config_),
        line_(line),
        core_mhz_(preset.clock_ghz * 1000) {}

  // Cycles from arrival at `at` to data, for one line read at addr.
  double read(uint64_t addr, Cycle at) {
    controller_.enqueue(next_id_++, addr, line_, false, at);
    std::vector<DramReadDone> done;
    controller_.advance(at + 100000, done);
    last_ = at + 100000;
    return done.empty() ? NAN : double(done.back().ready - at);
  }
  Cycle idle_after() const { return last_ + 1; }
  // The first line-aligned address after `from` in the same channel and bank as `base`, in
  // the same row or (same_row false) another.
  uint64_t neighbour(uint64_t base, bool same_row) const {
    DramAddress b = map_.decode(base);
    for (uint64_t addr = base + line_;; addr += line_) {
      DramAddress a = map_.decode(addr);
      bool bank =
          a.channel == b.channel && a.rank == b.rank && a.group == b.group && a.bank == b.bank;
      if (bank && (a.row == b.row) == same_row && a.column != b.column) return addr;
    }
  }
  // Core cycles of a read whose first command waits `before` DRAM clocks after its arrival
  // clock: before + the line's column commands (tCCD_L apart in one bank) + tCL + a burst,
  // counted from the arrival at core cycle `at`, plus the controller.
  double expected(Cycle at, double before) const {
    const DramTiming& t = config_.timing;
    double bursts = std::ceil(double(line_) / config_.burst_bytes());
    double arrival = std::ceil(at * config_.clock_mhz / core_mhz_ - 1e-9);
    double end = arrival + before + (bursts - 1) * t.tCCD_L + t.tCL + config_.burst_clocks();
    return std::ceil(end * core_mhz_ / config_.clock_mhz - 1e-9) + config_.controller_latency -
           double(at);
  }
  const BankedDramConfig& config() const { return config_; }
  // Whether every burst of the line at addr is in the same channel, bank and row.
  bool one_bank(uint64_t addr) const {
    DramAddress first = map_.decode(addr);
    for (uint32_t b = 1; b * config_.burst_bytes() < line_; ++b) {
      DramAddress a = map_.decode(addr + b * config_.burst_bytes());
      if (a.channel != first.channel || a.rank != first.rank || a.group != first.group ||
          a.bank != first.bank || a.row != first.row)
        return false;
    }
    return true;
  }

 private:
  static BankedDramConfig without_refresh(BankedDramConfig c) {
    c.refresh = DramRefresh::None;
    return c;
  }
  BankedDramConfig config_;
  DramController controller_;
  DramAddressMap map_;
  uint32_t line_;
  double core_mhz_;
  uint64_t next_id_ = 0;
  Cycle last_ = 0;
};

std::vector<Check> dram_ladder(const Target& target) {
  const HwConfig& preset = target.config;
  std::vector<Check> out;
  const char* names[3] = {"ladder.dram_closed", "ladder.dram_row_hit", "ladder.dram_conflict"};
  const char* titles[3] = {"one line read to a closed bank (ACT, RD)",
                           "one line read to the open row (RD)",
                           "one line read to another row of an open bank (PRE, ACT, RD)"};
  if (preset.dram_model != DramModel::Banked) {
    for (int i = 0; i < 3; ++i) {
      Check c{names[i], "closed_form", titles[i]};
      c.skipped = "dram.model is simple: one fixed latency, no rows";
      out.push_back(c);
    }
    return out;
  }
  DramProbe probe(preset, target.as_run(preset), block_bytes(last_level(preset).cache));
  if (!probe.one_bank(0)) {
    for (int i = 0; i < 3; ++i) {
      Check c{names[i], "closed_form", titles[i]};
      c.skipped =
          "dram.mapping spreads a line's bursts over several banks or channels: the "
          "rungs' closed form is for a line in one bank";
      out.push_back(c);
    }
    return out;
  }
  const DramTiming& t = probe.config().timing;
  bool open = probe.config().page_policy == DramPagePolicy::Open;
  uint64_t base = 0;
  double measured[3];
  Cycle at[3];
  uint64_t addrs[3] = {base, probe.neighbour(base, true), probe.neighbour(base, false)};
  for (int i = 0; i < 3; ++i) {
    at[i] = i == 0 ? 0 : probe.idle_after();
    measured[i] = probe.read(addrs[i], at[i]);
  }
  double before[3] = {double(t.tRCD_RD), open ? 0.0 : double(t.tRCD_RD),
                      open ? double(t.tRP + t.tRCD_RD) : double(t.tRCD_RD)};
  const char* sums[3] = {"tRCD_RD", open ? "0" : "tRCD_RD (closed page: the row was closed)",
                         open ? "tRP + tRCD_RD" : "tRCD_RD (closed page: the row was closed)"};
  for (int i = 0; i < 3; ++i) {
    Check c{names[i], "closed_form", titles[i]};
    c.unit = "cycles";
    c.source = fmt::format(
        "formula: {} + (bursts - 1) x tCCD_L + tCL + burst, in DRAM clocks ({} MHz) rounded up to "
        "core cycles, + dram.controller_latency {}",
        sums[i], probe.config().clock_mhz, probe.config().controller_latency);
    set_exact(c, probe.expected(at[i], before[i]));
    c.measured = measured[i];
    c.detail = fmt::format("DramController alone, refresh off, a {}-byte read at {:#x}",
                           block_bytes(last_level(preset).cache), addrs[i]);
    c.look_at =
        "DramController::decide and DramChannel (model/mem/dram_controller.cpp, "
        "dram_device.cpp)";
    out.push_back(c);
  }
  return out;
}

}  // namespace

std::vector<Check> latency_ladder(const Target& target) {
  std::vector<Check> out = ray_ladder(target);
  for (Check& c : dram_ladder(target)) out.push_back(c);
  return out;
}

}  // namespace rtsim::validation
