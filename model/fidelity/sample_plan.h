// Where the sampled fidelity level looks: the stream is cut into strata of equal length and
// one window of consecutive rays is measured in each (stratified sampling, as SMARTS does for
// instruction streams: Wunderlich et al., ISCA 2003). The windows' offsets within their strata
// follow a golden-ratio sequence from a seeded random start: spread evenly, they sample the
// horizontal structure of the image rows better than independent random offsets (on pica at
// 1920x1080, about 1.5x lower error at the same cost).
// Each window is preceded by warm-up rays that are simulated but not measured, so the caches,
// queues and ray slots are in their steady state when measurement begins. Between windows
// nothing is simulated and the machine keeps its state (caches stay as the last window left
// them). Consecutive rays are kept together because the coherence of neighbouring rays is
// what the caches see. With warm_pass (default) every window is first simulated once, unmeasured,
// so the measured pass finds no cold (compulsory) misses: in the full run a line misses cold
// once, in a sample its miss would be scaled up by the rate. The warm pass's excess over the
// measured pass (cycles, misses, DRAM bytes) is that cold-start cost, and is added back once.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rtsim {

// How the sampled level picks and times its sample: a scale model of the machine running 1 in
// `rate` warps (scaled_level.h, the default), or windows of consecutive rays on the full
// machine (this file, sampled_level.h).
// Warmed: the scale model with the other units' L2 traffic traced functionally (scaled_level.h).
enum class SampleMethod : uint8_t { ScaleModel, Windows, Warmed };
const char* sample_method_name(SampleMethod method);  // scale-model, windows, warmed
std::optional<SampleMethod> sample_method_from_name(const std::string& name);

struct SamplingConfig {
  SampleMethod method = SampleMethod::ScaleModel;
  uint32_t rate = 16;        // 1 in `rate` rays measured (the range: 4 to 64)
  uint32_t window_rays = 0;  // rays measured per window; 0: auto (4 x ray slots, >= 1024)
  int64_t warmup_rays = -1;  // rays simulated before each window; -1: auto (the ray slots)
  uint64_t seed = 1;      // seed of the window offsets; scale model: warps seed % rate + i x rate
  bool warm_pass = true;  // simulate every window once, unmeasured, before measuring
};

struct SampleWindow {
  uint64_t stratum_begin = 0, stratum_end = 0;  // the stratum, as stream positions
  uint64_t warm_begin = 0, begin = 0,
           end = 0;  // simulated [warm_begin, end), measured [begin, end)
};

struct SamplePlan {
  std::vector<SampleWindow> windows;  // in stream order, not overlapping
  uint32_t window_rays = 0, warmup_rays = 0;
  uint64_t measured_rays() const;
};

// Throws InputError if the stream has fewer than 2 x rate rays (no two strata to sample).
void check_sample_rate(uint64_t rays, uint32_t rate);

// Throws as check_sample_rate does.
SamplePlan plan_samples(uint64_t rays, const SamplingConfig& config, uint32_t ray_slots);

}  // namespace rtsim
