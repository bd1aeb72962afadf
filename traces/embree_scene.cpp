#include "traces/embree_scene.h"

#include <embree3/rtcore.h>

#include <cstring>
#include <stdexcept>
#include <string>

namespace rtsim {
namespace {

RTCRay to_rtc(const Ray& r) {
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
  out.mask = 0xffffffffu;
  out.id = 0;
  out.flags = 0;
  return out;
}

}  // namespace

EmbreeScene::EmbreeScene(const TriangleMesh& mesh, int threads) {
  std::string config = threads > 0 ? "threads=" + std::to_string(threads) : "";
  device_ = rtcNewDevice(config.c_str());
  if (!device_) throw std::runtime_error("Embree: cannot create a device");
  scene_ = rtcNewScene(device_);
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);

  RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  // Embree may read 16 bytes at the last vertex: the buffer gets one float of padding.
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
      mesh.positions.size() + 1));
  std::memcpy(vertices, mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
  auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t),
      mesh.triangles.size()));
  std::memcpy(indices, mesh.triangles.data(), mesh.triangles.size() * 3 * sizeof(uint32_t));
  rtcCommitGeometry(geom);
  rtcAttachGeometry(scene_, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(scene_);
}

EmbreeScene::~EmbreeScene() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
}

Hit EmbreeScene::intersect(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  rh.ray = to_rtc(ray);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rh);
  Hit hit;
  if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
    hit.t = rh.ray.tfar;
    hit.u = rh.hit.u;
    hit.v = rh.hit.v;
    hit.prim = rh.hit.primID;
  }
  return hit;
}

bool EmbreeScene::occluded(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r = to_rtc(ray);
  rtcOccluded1(scene_, &context, &r);
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
