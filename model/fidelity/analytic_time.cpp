#include "model/fidelity/analytic_time.h"

namespace rtsim {

AnalyticTime analytic_time(const HwConfig& c, const AnalyticInputs& in) {
  AnalyticTime out;
  auto add = [&out](const std::string& name, double cycles) {
    out.bounds.emplace_back(name, cycles);
    if (cycles > out.cycles) {
      out.cycles = cycles;
      out.bound = name;
    }
  };
  add("dispatch", double(in.rays) / c.dispatch.rays_per_cycle);
  add("dram", double(in.dram_bytes) / c.dram.bytes_per_cycle);
  for (size_t u = 0; u < in.units.size(); ++u) {
    const UnitWork& w = in.units[u];
    std::string p = "rt" + std::to_string(u);
    add(p + ".control", double(w.steps) / c.rt.issue_per_cycle);
    add(p + ".box", double(w.box_issues) / c.rt.box.count);
    add(p + ".triangle", double(w.triangle_issues) / c.rt.triangle.count);
    if (w.transform_issues > 0)
      add(p + ".transform", double(w.transform_issues) / c.rt.transform.count);
    add(p + ".warp_slots", w.warp_cycles / c.rt.warps);
  }
  out.cycles += in.mean_latency;
  return out;
}

}  // namespace rtsim
