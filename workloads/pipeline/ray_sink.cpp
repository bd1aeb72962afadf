#include "workloads/pipeline/ray_sink.h"

namespace rtsim::pipeline {

const char* pass_name(PassId pass) {
  static constexpr const char* kNames[kPassCount] = {
      "camera",   "shadow", "reflection", "reflected_shadow", "diffuse_gi",
      "gi_light", "ao",     "refraction", "translucency"};
  return kNames[size_t(pass)];
}

RayType pass_ray_type(PassId pass) {
  switch (pass) {
    case PassId::Camera: return RayType::Camera;
    case PassId::Shadow: return RayType::Shadow;
    case PassId::Reflection: return RayType::Reflection;
    case PassId::ReflectedShadow: return RayType::ReflectedShadow;
    case PassId::DiffuseGI: return RayType::DiffuseGI;
    case PassId::GiLight: return RayType::Shadow;
    case PassId::AO: return RayType::AO;
    case PassId::Refraction: return RayType::Refraction;
    case PassId::Translucency: return RayType::Translucency;
  }
  return RayType::Camera;
}

RaySink::RaySink(RayStreamWriter* writer, uint32_t width, uint32_t height, bool keep_density)
    : writer_(writer), frame_cost_(size_t(width) * height, 0) {
  if (keep_density)
    for (auto& d : density_) d.assign(size_t(width) * height, 0);
}

void RaySink::emit(const Ray& ray, uint32_t origin_prim, bool met_alpha) {
  bool on_screen = ray.pixel < frame_cost_.size();
  if (on_screen) frame_cost_[ray.pixel]++;
  if (ray.frame < warmup_frames_) return;
  Ray recorded = ray;
  recorded.frame -= warmup_frames_;
  if (writer_) writer_->write(recorded);
  counts_[size_t(pass_)]++;
  alpha_counts_[size_t(pass_)] += met_alpha;
  auto& density = density_[size_t(pass_)];
  if (on_screen && !density.empty()) density[ray.pixel]++;
  if (observer) observer(recorded, pass_, origin_prim);
}

uint64_t RaySink::total() const {
  uint64_t sum = 0;
  for (auto c : counts_) sum += c;
  return sum;
}

}  // namespace rtsim::pipeline
