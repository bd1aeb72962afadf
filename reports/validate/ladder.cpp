// The latency ladder: one ray alone on a one-triangle scene, its two reads served by the L1 or
// by the L2, and one read at a time to a closed, open and conflicting DRAM row, each against
// the sum of the configured latencies (model/VALIDATION.md).
#include <cmath>

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

std::vector<Check> ray_ladder(const Target& target) {
  const HwConfig& preset = target.config;
  OneTriangle scene(preset.bvh);
  HwConfig l1 = unloaded(preset);
  l1.rt_units = 1;
  l1.rt.warps = 1;
  l1.rt.warp_size = 1;
  l1.sim.warmup_rays = 1;
  // Two units: the second ray reaches the other unit, whose L1 is cold, long after the first
  // ray has left its data in the L2.
  HwConfig l2 = l1;
  l2.rt_units = 2;
  l2.dispatch.rays_per_cycle = 1.0 / 4096;
  std::vector<SimFigures> runs =
      simulate(target, {{l1, &scene.image, &scene.rays}, {l2, &scene.image, &scene.rays}});
  const RtCoreConfig& rt = preset.rt;
  double fixed = preset.dispatch.latency + rt.setup_latency + rt.box.latency + rt.triangle.latency +
                 2.0 * rt.control_latency;
  double l1_read = preset.l1.hit_latency;
  double l2_read = l1_read + 2.0 * preset.l2_layout.crossbar.latency + preset.l2.hit_latency;
  std::string terms = fmt::format(
      "dispatch.latency {} + rt.setup_latency {} + rt.box.latency {} + rt.triangle.latency {} + "
      "2 x rt.control_latency {}",
      preset.dispatch.latency, rt.setup_latency, rt.box.latency, rt.triangle.latency,
      rt.control_latency);
  Check hit1{"ladder.l1_hit", "closed_form", "one ray, both reads hit the L1"};
  hit1.source = "formula: " + terms + fmt::format(" + 2 reads x rt.l1.hit_latency {}", l1_read);
  hit1.unit = "cycles";
  set_exact(hit1, fixed + 2 * l1_read);
  hit1.measured = runs[0]["cycles"];
  hit1.detail =
      "1 unit, 1 ray slot, bandwidth limits off; the same ray twice, the first as "
      "warm-up; cycles from the second ray's dispatch to its retirement";
  hit1.look_at = "RtCore::on_ray, test_step, Cache::read (model/sched, model/mem)";
  Check hit2{"ladder.l2_hit", "closed_form", "one ray, both reads miss the L1 and hit the L2"};
  hit2.source =
      "formula: " + terms +
      fmt::format(
          " + 2 reads x (rt.l1.hit_latency {} + 2 x xbar.latency {} + "
          "l2.hit_latency {})",
          preset.l1.hit_latency, preset.l2_layout.crossbar.latency, preset.l2.hit_latency);
  hit2.unit = "cycles";
  set_exact(hit2, fixed + 2 * l2_read);
  hit2.measured = runs[1]["cycles"];
  hit2.detail =
      "2 units, 1 ray slot each, one ray dispatched every 4096 cycles: the second ray "
      "runs on the other unit after the first left its lines in the L2";
  hit2.look_at = "the L1 miss path: L1Module, Crossbar, SharedCacheModule (model/sc, model/mem)";
  return {hit1, hit2};
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
  DramProbe probe(preset, target.as_run(preset), block_bytes(preset.l2));
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
                           block_bytes(preset.l2), addrs[i]);
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
