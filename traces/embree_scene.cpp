#include "traces/embree_scene.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

#include "traces/host_clock.h"

namespace rtsim {
namespace {

RTCRay to_rtc(const Ray& r, uint32_t mask) {
  RTCRay out;
  out.org_x = r.org.x;
  out.org_y = r.org.y;
  out.org_z = r.org.z;
  out.dir_x = r.dir.x;
  out.dir_y = r.dir.y;
  out.dir_z = r.dir.z;
  out.tnear = r.tmin;
  out.tfar = r.tmax;
  out.time = 0.0f;
  out.mask = mask;
  out.id = 0;
  out.flags = 0;
  return out;
}

// Embree's context, extended (as Embree's documentation shows) with what the filter needs of
// the ray and what it reports back about the query.
struct RayContext {
  RTCIntersectContext embree;  // first, so that Embree's pointer to it is one to RayContext
  bool force_opaque;
  bool met_alpha = false;  // set by the filter
};

RayContext context_of(const Ray& ray) {
  RayContext context;
  rtcInitIntersectContext(&context.embree);
  context.force_opaque = ray.force_opaque;
  return context;
}

// Whether a candidate on a triangle of an alpha geometry counts as a hit: an opaque triangle's
// does (the filter is set per geometry, so they come here too); an alpha-tested one's where its
// mask is opaque at the hit, and the context notes that the query met one.
bool candidate_counts(RayContext& context, const TriangleAlpha& alpha, uint32_t prim, float u,
                      float v) {
  if (!alpha.tested(prim)) return true;
  context.met_alpha = true;
  return alpha.look_up(prim, u, v).opaque;
}

// Embree's intersection filter for alpha-tested triangles: a candidate whose mask has a hole
// at the hit is no hit, for closest-hit and any-hit queries alike, unless the ray forces
// every triangle opaque.
void alpha_filter(const RTCFilterFunctionNArguments* args) {
  auto& context = *reinterpret_cast<RayContext*>(args->context);
  if (context.force_opaque) return;
  const auto& alpha = *static_cast<const TriangleAlpha*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i)
    if (args->valid[i] == -1 &&
        !candidate_counts(context, alpha, RTCHitN_primID(args->hit, args->N, i),
                          RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i)))
      args->valid[i] = 0;
}

// A robust, high-quality scene of one triangle geometry; keeps the mesh's alpha alive in `keep`.
RTCScene mesh_scene(RTCDevice device, const TriangleMesh& mesh,
                    std::vector<std::shared_ptr<const TriangleAlpha>>& keep) {
  RTCScene scene = rtcNewScene(device);
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  // Embree may read 16 bytes at the last vertex: the buffer gets one float of padding.
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                               mesh.positions.size() + 1));
  std::memcpy(vertices, mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
  auto* indices = static_cast<uint32_t*>(
      rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(uint32_t), mesh.triangles.size()));
  std::memcpy(indices, mesh.triangles.data(), mesh.triangles.size() * 3 * sizeof(uint32_t));
  if (mesh.alpha) {
    keep.push_back(mesh.alpha);
    rtcSetGeometryUserData(geom, const_cast<TriangleAlpha*>(mesh.alpha.get()));
    rtcSetGeometryIntersectFilterFunction(geom, alpha_filter);
    rtcSetGeometryOccludedFilterFunction(geom, alpha_filter);
  }
  rtcCommitGeometry(geom);
  rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(scene);
  return scene;
}

}  // namespace

void EmbreeScene::open_device(int threads) {
  std::string config = threads > 0 ? "threads=" + std::to_string(threads) : "";
  device_ = rtcNewDevice(config.c_str());
  if (!device_) throw std::runtime_error("Embree: cannot create a device");
}

EmbreeScene::EmbreeScene(const TriangleMesh& mesh, int threads) {
  open_device(threads);
  scene_ = mesh_scene(device_, mesh, alphas_);
}

EmbreeScene::EmbreeScene(const InstancedMesh& geometry, int threads)
    : EmbreeScene(geometry, InstanceSettings{}, threads) {}

EmbreeScene::EmbreeScene(const InstancedMesh& geometry, const InstanceSettings& settings,
                         int threads)
    : settings_(settings) {
  open_device(threads);
  for (const TriangleMesh& mesh : geometry.meshes)
    mesh_scenes_.push_back(mesh_scene(device_, mesh, alphas_));
  std::vector<RTCGeometry> geometries(geometry.instances.size(), nullptr);
  std::vector<bool> moving(geometry.instances.size(), false);
  for (const auto& [instance, motion] : settings.moving) moving[instance] = true;
  uint32_t frames = settings.animated() ? settings.frames : 1;
  for (uint32_t f = 0; f < frames; ++f) {
    double start = wall_seconds();
    RTCScene top = build_top(instances_at(geometry.instances, settings, f), geometries, moving);
    top_seconds_.push_back(wall_seconds() - start);
    (f == 0 ? scene_ : frame_scenes_.emplace_back()) = top;
  }
  for (RTCGeometry geom : geometries) rtcReleaseGeometry(geom);
}

RTCScene EmbreeScene::build_top(const std::vector<Instance>& instances,
                                std::vector<RTCGeometry>& geometries,
                                const std::vector<bool>& moving) {
  RTCScene top = rtcNewScene(device_);
  rtcSetSceneFlags(top, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(top, RTC_BUILD_QUALITY_HIGH);
  for (size_t i = 0; i < instances.size(); ++i) {
    const Instance& instance = instances[i];
    if (!geometries[i] || moving[i]) {
      if (geometries[i]) rtcReleaseGeometry(geometries[i]);
      RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
      rtcSetGeometryInstancedScene(geom, mesh_scenes_[instance.mesh]);
      float xfm[12];  // 3x4 column major: the linear part's columns, then the offset
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) xfm[c * 3 + r] = instance.to_world.linear[c][r];
      for (int r = 0; r < 3; ++r) xfm[9 + r] = instance.to_world.offset[r];
      rtcSetGeometryTransform(geom, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
      rtcSetGeometryMask(geom, instance.mask);
      rtcCommitGeometry(geom);
      geometries[i] = geom;
    }
    rtcAttachGeometry(top, geometries[i]);  // geometry ids in instance order: id = instance index
  }
  rtcCommitScene(top);
  return top;
}

RTCScene EmbreeScene::scene_of(const Ray& ray) const {
  uint32_t pose = frame_scenes_.empty() ? 0 : settings_.pose_frame(ray.frame);
  return pose == 0 ? scene_ : frame_scenes_[pose - 1];
}

EmbreeScene::~EmbreeScene() {
  if (scene_) rtcReleaseScene(scene_);
  for (RTCScene scene : frame_scenes_) rtcReleaseScene(scene);
  for (RTCScene scene : mesh_scenes_) rtcReleaseScene(scene);
  if (device_) rtcReleaseDevice(device_);
}

Hit EmbreeScene::intersect(const Ray& ray, bool* met_alpha) const {
  RayContext context = context_of(ray);
  RTCRayHit rh;
  rh.ray = to_rtc(ray, settings_.ray_masks[size_t(ray.type)]);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_of(ray), &context.embree, &rh);
  Hit hit;
  if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
    hit.t = rh.ray.tfar;
    hit.u = rh.hit.u;
    hit.v = rh.hit.v;
    hit.prim = rh.hit.primID;
    if (rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID) hit.instance = rh.hit.instID[0];
  }
  if (met_alpha) *met_alpha = context.met_alpha;
  return hit;
}

bool EmbreeScene::occluded(const Ray& ray, bool* met_alpha) const {
  RayContext context = context_of(ray);
  RTCRay r = to_rtc(ray, settings_.ray_masks[size_t(ray.type)]);
  rtcOccluded1(scene_of(ray), &context.embree, &r);
  if (met_alpha) *met_alpha = context.met_alpha;
  return r.tfar == -std::numeric_limits<float>::infinity();
}

Hit EmbreeScene::trace(const Ray& ray) const {
  if (ray.query == Query::ClosestHit) return intersect(ray);
  Hit hit;
  if (occluded(ray)) {
    hit.t = ray.tmax;
    hit.prim = kAnyPrim;
  }
  return hit;
}

}  // namespace rtsim
