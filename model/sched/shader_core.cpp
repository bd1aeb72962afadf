#include "model/sched/shader_core.h"

#include <algorithm>
#include <sstream>

#include "model/sched/ray_context.h"

namespace rtsim {

const char* shader_model_name(ShaderModel model) {
  return model == ShaderModel::Simt ? "simt" : "none";
}

// Warp instructions of each shader body, estimated for SEED's hybrid passes (model/SIM.md,
// "The shader side"): ray generation reads the G-buffer and builds the ray; hit shading of
// the camera, reflection, refraction and GI rays evaluates a material and its lighting;
// shadow, AO and reflected-shadow rays end at any hit and only their miss shader runs.
std::array<ShaderCycles, kRayTypeCount> ShaderConfig::default_shader_cycles() {
  std::array<ShaderCycles, kRayTypeCount> c{};
  c[int(RayType::Camera)] = {20, 150, 20};
  c[int(RayType::Shadow)] = {40, 0, 10};
  c[int(RayType::Reflection)] = {40, 300, 30};
  c[int(RayType::ReflectedShadow)] = {20, 0, 10};
  c[int(RayType::DiffuseGI)] = {50, 200, 30};
  c[int(RayType::AO)] = {40, 0, 10};
  c[int(RayType::Refraction)] = {40, 300, 30};
  c[int(RayType::Translucency)] = {40, 50, 10};
  return c;
}

std::string shader_config_problem(const ShaderConfig& c) {
  if (c.warps == 0) return "warps must be at least 1";
  if (c.schedulers == 0) return "schedulers must be at least 1";
  return {};
}

uint64_t shading_address(uint32_t frame, uint32_t pixel, uint32_t bytes_per_hit) {
  constexpr uint64_t kRegion = kTextureBase - kShadingBase;
  uint64_t slot = (uint64_t(frame) << 32) + pixel;
  return kShadingBase + slot % (kRegion / bytes_per_hit) * bytes_per_hit;
}

ShaderCore::ShaderCore(const ShaderConfig& config, RaySupply& upstream, MemoryTarget& memory,
                       std::function<void(Cycle)> wake)
    : config_(config),
      upstream_(upstream),
      memory_(memory),
      wake_(std::move(wake)),
      warps_(config.warps),
      scheduler_free_(config.schedulers, 0) {}

Cycle ShaderCore::occupy(Cycle at, uint64_t cycles) {
  if (cycles == 0) return at;
  auto first = std::min_element(scheduler_free_.begin(), scheduler_free_.end());
  *first = std::max(at, *first) + cycles;
  return *first;
}

uint64_t ShaderCore::cycles_of(uint32_t types, uint32_t ShaderCycles::*phase,
                               uint64_t& phase_total) {
  uint64_t sum = 0;
  for (int t = 0; t < kRayTypeCount; ++t) {
    if (!(types >> t & 1)) continue;
    uint32_t c = config_.cycles[t].*phase;
    stats_.type_cycles[t] += c;
    sum += c;
  }
  phase_total += sum;
  return sum;
}

size_t ShaderCore::take(uint32_t unit, Cycle now, size_t max, std::vector<RayContext*>& out) {
  if (upstream_.exhausted()) return 0;
  auto slot =
      std::find_if(warps_.begin(), warps_.end(), [&](const Warp& w) { return w.free_at <= now; });
  if (slot == warps_.end()) {
    if (starved_since_ == kPending) {
      starved_since_ = now;
      stats_.slot_waits++;
    }
    Cycle next = next_wake(now);
    if (next != kPending) wake_(next);
    return 0;
  }
  if (starved_since_ != kPending) {
    stats_.slot_wait_cycles += now - starved_since_;
    starved_since_ = kPending;
  }
  size_t first = out.size();
  size_t n = upstream_.take(unit, now, max, out);
  if (n == 0) return 0;
  auto index = uint32_t(slot - warps_.begin());
  Warp& w = *slot;
  w.free_at = kPending;
  w.tracing = uint32_t(n);
  w.miss_types = 0;
  w.hits.clear();
  uint32_t types = 0;
  for (size_t i = first; i < out.size(); ++i) types |= 1u << int(out[i]->ray.type);
  Cycle arrive = occupy(now, cycles_of(types, &ShaderCycles::raygen, stats_.raygen_cycles)) +
                 config_.trace_latency;
  for (size_t i = first; i < out.size(); ++i) {
    RayContext& ray = *out[i];
    ray.shader_warp = index;
    if (arrive > ray.ready) {
      stats_.trace_delay_cycles += arrive - ray.ready;
      ray.ready = arrive;
    }
  }
  stats_.warps++;
  stats_.rays += n;
  return n;
}

void ShaderCore::retire(RayContext& ray, Cycle now) {
  uint32_t index = ray.shader_warp;
  Warp& w = warps_[index];
  if (ray.state.prim != kNoHit)
    w.hits.push_back({ray.ray.pixel, ray.ray.frame, ray.ray.type});
  else
    w.miss_types |= 1u << int(ray.ray.type);
  upstream_.retire(ray, now);
  if (--w.tracing == 0) shade(index, now);
}

void ShaderCore::shade(uint32_t index, Cycle now) {
  Warp& w = warps_[index];
  uint32_t hit_types = 0;
  for (const Warp::HitRay& hit : w.hits) hit_types |= 1u << int(hit.type);
  uint64_t cycles = cycles_of(hit_types, &ShaderCycles::hit, stats_.hit_cycles) +
                    cycles_of(w.miss_types, &ShaderCycles::miss, stats_.miss_cycles);
  w.shaded = occupy(now + config_.trace_latency, cycles);
  stats_.hits += w.hits.size();
  if (config_.bytes_per_hit > 0) {
    for (auto [pixel, frame, type] : w.hits) {
      ReadCharge charge;
      uint64_t addr = shading_address(frame, pixel, config_.bytes_per_hit);
      uint64_t token = uint64_t(index) * kRayTypeCount + uint64_t(type);
      Cycle ready = memory_.read(addr, config_.bytes_per_hit, now, this, token, charge);
      stats_.reads[int(type)] += charge;
      stats_.read_bytes += config_.bytes_per_hit;
      if (ready == kPending)
        w.pending_reads++;
      else
        w.shaded = std::max(w.shaded, ready);
    }
  }
  if (w.pending_reads > 0)
    shading_reads_++;
  else
    free_slot(index);
}

// token: the warp's index and the hit ray's type.
void ShaderCore::read_done(uint64_t token, Cycle ready, const ReadCharge& charge) {
  auto index = uint32_t(token / kRayTypeCount);
  Warp& w = warps_[index];
  stats_.reads[token % kRayTypeCount] += charge;
  w.shaded = std::max(w.shaded, ready);
  if (--w.pending_reads > 0) return;
  shading_reads_--;
  free_slot(index);
  if (exhausted()) wake_(w.free_at);  // the unit may wait for the last reads to finish
}

void ShaderCore::free_slot(uint32_t index) {
  Warp& w = warps_[index];
  w.free_at = w.shaded;
  stats_.last_cycle = std::max(stats_.last_cycle, w.free_at);
  if (starved_since_ != kPending) wake_(w.free_at);
}

Cycle ShaderCore::next_wake(Cycle now) const {
  Cycle next = kPending;
  if (starved_since_ == kPending && !upstream_.exhausted()) return next;
  for (const Warp& w : warps_)
    if (w.free_at >= now) next = std::min(next, w.free_at);
  return next;
}

ShaderStats& ShaderStats::operator+=(const ShaderStats& o) {
  warps += o.warps;
  rays += o.rays;
  hits += o.hits;
  raygen_cycles += o.raygen_cycles;
  hit_cycles += o.hit_cycles;
  miss_cycles += o.miss_cycles;
  trace_delay_cycles += o.trace_delay_cycles;
  slot_waits += o.slot_waits;
  slot_wait_cycles += o.slot_wait_cycles;
  read_bytes += o.read_bytes;
  for (int t = 0; t < kRayTypeCount; ++t) {
    type_cycles[t] += o.type_cycles[t];
    reads[t] += o.reads[t];
  }
  last_cycle = std::max(last_cycle, o.last_cycle);
  return *this;
}

std::string ShaderCore::dump() const {
  uint32_t tracing = 0, reading = 0;
  for (const Warp& w : warps_) {
    tracing += w.tracing > 0;
    reading += w.pending_reads > 0;
  }
  std::ostringstream out;
  out << "  shader: " << tracing << " of " << warps_.size() << " warps tracing, " << reading
      << " waiting for shading reads"
      << (starved_since_ != kPending ? ", unit waits for a warp" : "") << "\n";
  return out.str();
}

}  // namespace rtsim
