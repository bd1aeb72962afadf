#include "model/fidelity/sample_plan.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "traces/error.h"

namespace rtsim {

uint64_t SamplePlan::measured_rays() const {
  uint64_t n = 0;
  for (const SampleWindow& w : windows) n += w.end - w.begin;
  return n;
}

const char* sample_method_name(SampleMethod method) {
  switch (method) {
    case SampleMethod::ScaleModel: return "scale-model";
    case SampleMethod::Windows: return "windows";
    case SampleMethod::Warmed: return "warmed";
  }
  return "";
}

std::optional<SampleMethod> sample_method_from_name(const std::string& name) {
  for (SampleMethod m : {SampleMethod::ScaleModel, SampleMethod::Windows, SampleMethod::Warmed})
    if (name == sample_method_name(m)) return m;
  return std::nullopt;
}

void check_sample_rate(uint64_t rays, uint32_t rate) {
  if (rays < 2ull * std::max<uint32_t>(rate, 1))
    throw InputError("sampling: the stream has " + std::to_string(rays) +
                     " rays, too few to sample 1 in " + std::to_string(rate));
}

SamplePlan plan_samples(uint64_t rays, const SamplingConfig& config, uint32_t ray_slots) {
  check_sample_rate(rays, config.rate);
  uint64_t rate = std::max<uint32_t>(config.rate, 1);
  SamplePlan plan;
  plan.window_rays =
      config.window_rays ? config.window_rays : std::max<uint32_t>(1024, 4 * ray_slots);
  plan.warmup_rays = config.warmup_rays >= 0 ? uint32_t(config.warmup_rays) : ray_slots;
  uint64_t strata = rays / (rate * plan.window_rays);
  if (strata < 2) {
    strata = 2;
    plan.window_rays = uint32_t(std::max<uint64_t>(1, rays / (strata * rate)));
  }
  // Offsets: a golden-ratio sequence from a seeded random start, so windows fall at evenly
  // spread positions within their strata (and across the image rows the strata cut).
  std::mt19937_64 rng(config.seed);
  double position = double(rng() >> 11) * 0x1p-53;
  const double golden = 0.6180339887498949;
  uint64_t previous_end = 0;
  for (uint64_t h = 0; h < strata; ++h) {
    SampleWindow w;
    w.stratum_begin = h * rays / strata;
    w.stratum_end = (h + 1) * rays / strata;
    uint64_t length = w.stratum_end - w.stratum_begin;
    uint64_t measured = std::min<uint64_t>(plan.window_rays, length);
    w.begin = w.stratum_begin + uint64_t(position * double(length - measured));
    position = std::fmod(position + golden, 1.0);
    w.end = w.begin + measured;
    w.warm_begin = std::max(previous_end, w.begin - std::min<uint64_t>(w.begin, plan.warmup_rays));
    previous_end = w.end;
    plan.windows.push_back(w);
  }
  return plan;
}

}  // namespace rtsim
