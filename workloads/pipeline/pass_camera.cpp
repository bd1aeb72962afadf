#include "workloads/pipeline/pass_camera.h"

namespace rtsim::pipeline {

GBuffer run_camera_pass(const FrameContext& ctx, const std::vector<SamplePosition>& positions,
                        RaySink* sink) {
  GBuffer g;
  g.width = ctx.width;
  g.height = ctx.height;
  g.samples.resize(positions.size());
  if (sink) sink->set_pass(PassId::Camera);
  for (size_t i = 0; i < positions.size(); ++i) {
    const SamplePosition& p = positions[i];
    Ray ray = ctx.ray(RayType::Camera, Query::ClosestHit);
    ray.org = ctx.camera.position;
    ray.dir = ctx.camera.direction(p.sx, p.sy);
    ray.pixel = p.pixel;
    ray.sample = p.index;
    Hit hit = sink ? ctx.scene.shoot_closest(*sink, ray) : ctx.scene.intersect(ray);
    GSample& s = g.samples[i];
    s.sx = p.sx;
    s.sy = p.sy;
    s.pixel = p.pixel;
    s.index = p.index;
    s.view = ray.dir;
    s.surface = surface_at(ctx.scene.materials.triangles, ray, hit);
    if (s.surface.hit()) {
      s.depth = hit.t;
      s.material = ctx.scene.materials.index_of(hit.prim);
    }
  }
  return g;
}

}  // namespace rtsim::pipeline
