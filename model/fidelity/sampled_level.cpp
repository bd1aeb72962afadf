#include "model/fidelity/sampled_level.h"

#include <algorithm>
#include <cstdlib>
#include <functional>

#include "model/fidelity/cache_hierarchy.h"
#include "model/fidelity/ray_charge.h"
#include "model/fidelity/ray_range_reader.h"
#include "model/fidelity/stratified.h"
#include "model/sc/rt_simulator.h"
#include "model/sched/ray_source.h"

namespace rtsim {
namespace {

struct WindowMeasure {
  uint64_t first = 0, last = 0;  // measured rays as simulation sequence numbers [first, last)
  Cycle begin = 0, end = 0;      // when the retired count reached first and last
  std::array<CostTotals, kRayTypeCount> by_type{};
};

// The simulated sequence: the warm pass (each window's rays), then the measured pass (each
// window after its warm-up rays), with where each window lies in it.
struct SampledSequence {
  std::vector<Ray> rays;
  std::vector<WindowMeasure> warm, measured;
};

SampledSequence build_sequence(RayRangeReader& reader, const SamplePlan& plan, bool warm_pass) {
  SampledSequence s;
  for (const SampleWindow& w : plan.windows) {
    size_t start = s.rays.size();
    reader.read(w.warm_begin, w.end, s.rays);
    WindowMeasure m;
    m.first = start + (w.begin - w.warm_begin);
    m.last = s.rays.size();
    s.measured.push_back(m);
  }
  if (!warm_pass) return s;
  std::vector<Ray> warm;
  for (size_t j = 0; j < plan.windows.size(); ++j) {
    WindowMeasure m;
    m.first = warm.size();
    warm.insert(warm.end(), s.rays.begin() + long(s.measured[j].first),
                s.rays.begin() + long(s.measured[j].last));
    m.last = warm.size();
    s.warm.push_back(m);
  }
  for (WindowMeasure& m : s.measured) {
    m.first += warm.size();
    m.last += warm.size();
  }
  s.rays.insert(s.rays.begin(), warm.begin(), warm.end());
  return s;
}

// Charges each retired ray to its window and times the windows by the retired count.
class WindowCollector : public RayRetireListener {
 public:
  explicit WindowCollector(SampledSequence& s) {
    for (auto* list : {&s.warm, &s.measured})
      for (WindowMeasure& w : *list) windows_.push_back(&w);
  }

  void retired(const RayContext& ray, Cycle now) override {
    ++retired_;
    for (; mark_ < 2 * windows_.size(); ++mark_) {
      WindowMeasure& w = *windows_[mark_ / 2];
      uint64_t count = mark_ % 2 ? w.last : w.first;
      if (count > retired_) break;
      (mark_ % 2 ? w.end : w.begin) = count == 0 ? 0 : now;
    }
    auto it = std::upper_bound(windows_.begin(), windows_.end(), ray.sequence,
                               [](uint64_t s, const WindowMeasure* w) { return s < w->first; });
    if (it == windows_.begin() || ray.sequence >= (*(it - 1))->last) return;
    charge_retired_ray((*(it - 1))->by_type, ray, now);
  }

 private:
  std::vector<WindowMeasure*> windows_;  // warm then measured: sequence order
  uint64_t retired_ = 0;
  size_t mark_ = 0;
};

using Field = std::function<double(const CostTotals&)>;

double field_sum(const WindowMeasure& w, const Field& field, int type) {
  double v = 0;
  for (int t = 0; t < kRayTypeCount; ++t)
    if (type < 0 || t == type) v += field(w.by_type[t]);
  return v;
}

double span(const WindowMeasure& w) {
  return double(w.end - std::min(w.end, w.begin));
}

// Scaled per-stratum values of the measured pass, and the warm pass's excess (cold start).
struct Scaled {
  std::vector<double> strata;
  double excess = 0;
};

class Estimator {
 public:
  Estimator(const SamplePlan& plan, const SampledSequence& s) : s_(s) {
    for (const SampleWindow& w : plan.windows)
      scale_.push_back(double(w.stratum_end - w.stratum_begin) / double(w.end - w.begin));
  }

  Scaled scaled(const std::function<double(const WindowMeasure&)>& value) const {
    Scaled out;
    for (size_t j = 0; j < s_.measured.size(); ++j) {
      out.strata.push_back(scale_[j] * value(s_.measured[j]));
      if (!s_.warm.empty()) out.excess += value(s_.warm[j]) - value(s_.measured[j]);
    }
    return out;
  }
  Scaled scaled(const Field& field, int type = -1) const {
    return scaled([&](const WindowMeasure& w) { return field_sum(w, field, type); });
  }
  Estimate total(const Scaled& t) const { return total_estimate(t.strata, t.excess); }
  Estimate ratio(const Field& y, const Field& x, int type = -1) const {
    Scaled sy = scaled(y, type), sx = scaled(x, type);
    return ratio_estimate(sy.strata, sx.strata, sy.excess, sx.excess);
  }

 private:
  const SampledSequence& s_;
  std::vector<double> scale_;
};

// Each cache level's hit rate, over the rays of `type` (-1: all).
LevelEstimates level_estimates(const Estimator& e, const std::vector<std::string>& names,
                               int type = -1) {
  LevelEstimates out;
  for (size_t i = 0; i < names.size(); ++i) {
    Field hits = [i](const CostTotals& c) { return double(c.reads.hits[i]); };
    Field accesses = [i](const CostTotals& c) { return double(c.reads.accesses[i]); };
    out.push_back({names[i], e.ratio(hits, accesses, type)});
  }
  return out;
}

void estimate(FidelityResult& r, const SamplePlan& plan, const SampledSequence& s,
              const std::vector<std::string>& levels) {
  Estimator e(plan, s);
  Field rays = [](const CostTotals& c) { return double(c.rays); };
  Field nodes = [](const CostTotals& c) { return double(c.nodes); };
  Field tris = [](const CostTotals& c) { return double(c.triangles); };
  Field dram = [](const CostTotals& c) { return double(c.reads.dram_bytes); };
  Field latency = [](const CostTotals& c) { return c.latency; };
  Scaled cycles = e.scaled(span);
  cycles.excess += e.ratio(latency, rays).value;  // filling and draining the pipeline
  r.cycles = e.total(cycles);
  r.dram_bytes = e.total(e.scaled(dram));
  r.levels = level_estimates(e, levels);
  r.nodes_per_ray = e.ratio(nodes, rays);
  r.triangles_per_ray = e.ratio(tris, rays);
  for (int t = 0; t < kRayTypeCount; ++t) {
    TypeEstimate& te = r.types[t];
    te.nodes_per_ray = e.ratio(nodes, rays, t);
    te.triangles_per_ray = e.ratio(tris, rays, t);
    te.levels = level_estimates(e, levels, t);
    te.dram_bytes_per_ray = e.ratio(dram, rays, t);
    te.latency_mean = e.ratio(latency, rays, t);
  }
}

}  // namespace

FidelityResult run_sampled_level(const HwConfig& config, BvhView image, const std::string& stream,
                                 const SamplingConfig& sampling) {
  setenv("SYSC_DISABLE_COPYRIGHT_MESSAGE", "1", 1);
  HostTimer timer;
  RayRangeReader reader(stream);
  const StreamHeader& header = reader.header();
  SamplePlan plan = plan_samples(header.total_rays(), sampling, ray_slots(config));
  SampledSequence sequence = build_sequence(reader, plan, sampling.warm_pass);
  VectorRaySource source(sequence.rays);
  WindowCollector collector(sequence);
  RtSimulator sim(config, image, source, 0, 0, &collector);
  sim.run();
  FidelityResult r;
  r.level = FidelityLevel::Sampled;
  r.sample_rate = sampling.rate;
  r.sample_method = sample_method_name(SampleMethod::Windows);
  r.rays = header.total_rays();
  r.simulated_rays = sequence.rays.size();
  r.measured_rays = plan.measured_rays();
  r.strata = uint32_t(plan.windows.size());
  r.clock_ghz = config.clock_ghz;
  r.time_model = "cycle-approximate model on " + std::to_string(r.strata) + " windows of " +
                 std::to_string(plan.window_rays) + " rays after " +
                 std::to_string(plan.warmup_rays) + " warm-up rays" +
                 (sampling.warm_pass ? ", warm pass first" : "");
  for (int t = 0; t < kRayTypeCount; ++t) r.types[t].rays = header.counts[t];
  estimate(r, plan, sequence, level_names(config.memory));
  timer.stop(r);
  return r;
}

}  // namespace rtsim
