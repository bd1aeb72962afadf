// DRAM latency under load: line reads at consecutive addresses arriving at random (exponential
// gaps, seeded) at 10% to 80% of the data buses' peak; the mean read latency against the
// utilisation must follow a queueing curve W(u) = W0 + a u / (1 - u), W0 the unloaded latency
// and a fitted by least squares (the M/D/1 and M/M/1 waits have this form).
#include <cmath>

#include <fmt/core.h>

#include "model/mem/dram_controller.h"
#include "model/verify/ray_samples.h"
#include "reports/validate/checks.h"

namespace rtsim::validation {
namespace {

struct LoadPoint {
  double utilisation = 0, latency = 0;
};

LoadPoint run_load(const HwConfig& run, uint32_t line, double offered, uint64_t seed) {
  const uint64_t reads = 20000;
  DramController controller(run.banked_dram, run.clock_ghz);
  double peak = run.banked_dram.peak_gb_per_s() / run.clock_ghz;  // bytes per core cycle
  double gap = line / (offered * peak);                           // mean cycles between reads
  SeededRandom random(seed);
  std::vector<DramReadDone> done;
  double at = 0;
  for (uint64_t i = 0; i < reads; ++i) {
    at += -gap * std::log(1.0 - random.uniform());
    if (Cycle(at) > 0) controller.advance(Cycle(at) - 1, done);  // decisions before it arrives
    controller.enqueue(i, i * line, line, false, Cycle(at));
  }
  drain(controller, reads, Cycle(at), done);
  double latency = 0;
  for (const DramReadDone& d : done) latency += double(d.ready);
  // Arrival cycles again, from the same seed.
  SeededRandom again(seed);
  double arrivals = 0, t = 0;
  for (uint64_t i = 0; i < reads; ++i) {
    t += -gap * std::log(1.0 - again.uniform());
    arrivals += double(Cycle(t));
  }
  LoadPoint p;
  p.latency = (latency - arrivals) / double(reads);
  p.utilisation = double(reads * line) / (t * peak);
  return p;
}

}  // namespace

Check dram_loaded_latency(const Target& target) {
  Check c{"queueing.dram_latency", "closed_form",
          "DRAM read latency against utilisation follows a queueing curve up to 80%"};
  c.unit = "worst deviation";
  if (target.config.dram_model != DramModel::Banked) {
    c.skipped = "dram.model is simple: its queue is one bus, checked by its unit tests";
    return c;
  }
  HwConfig run = target.as_run(target.config);
  uint32_t line = block_bytes(last_level(target.config).cache);
  std::vector<LoadPoint> points;
  for (int step = 1; step <= 8; ++step) points.push_back(run_load(run, line, 0.1 * step, step));
  // W0: the unloaded latency (10% load); a: least squares of W - W0 against u / (1 - u).
  double w0 = points[0].latency, num = 0, den = 0;
  for (const LoadPoint& p : points) {
    double x = p.utilisation / (1 - p.utilisation);
    num += x * (p.latency - w0);
    den += x * x;
  }
  double a = num / den, worst = 0;
  std::string table;
  for (const LoadPoint& p : points) {
    double fit = w0 + a * p.utilisation / (1 - p.utilisation);
    worst = std::max(worst, std::abs(p.latency - fit) / fit);
    table +=
        fmt::format("{}{:.0f}%: {:.1f}", table.empty() ? "" : ", ", 100 * p.utilisation, p.latency);
  }
  c.expected = 0;
  c.lo = 0;
  c.hi = 0.10;
  c.measured = worst;
  c.source =
      "formula: W(u) = W0 + a u / (1 - u) (queueing theory: M/D/1 and M/M/1 waits); "
      "pass: every point within 10% of the fitted curve";
  c.detail = fmt::format(
      "DramController alone, {}-byte reads at consecutive addresses, "
      "exponential gaps, 20000 reads per load; mean latency in cycles by "
      "utilisation: {}; fit W0 {:.1f}, a {:.2f}",
      line, table, w0, a);
  c.look_at = "DramController scheduling and queues (read_queue, starvation_cap)";
  return c;
}

}  // namespace rtsim::validation
