#include "traces/stream_codec.h"

#include <cstring>

#include <fmt/core.h>

#include "traces/bytes.h"
#include "traces/hash.h"

namespace rtsim {
namespace {

constexpr uint8_t kForceOpaqueBit = 2;  // of a ray record's query byte (traces/FORMAT.md)

}  // namespace

uint64_t StreamHeader::total_rays() const {
  uint64_t total = 0;
  for (auto c : counts) total += c;
  return total;
}

std::string grid_problem(const StreamHeader& h) {
  if (h.frame_count > kMaxFrames)
    return fmt::format("{} frames: more than {}", h.frame_count, kMaxFrames);
  if (h.width > kMaxGridSide || h.height > kMaxGridSide)
    return fmt::format("pixel grid {} x {}: a side is beyond {}", h.width, h.height, kMaxGridSide);
  if ((h.width == 0) != (h.height == 0))
    return fmt::format("pixel grid {} x {}: one side is 0 (0 x 0 is no grid)", h.width, h.height);
  return {};
}

std::string ray_outside_header(const Ray& ray, const StreamHeader& h) {
  if (ray.frame >= h.frame_count)
    return fmt::format("frame {} is beyond the header's {} frames", ray.frame, h.frame_count);
  if (h.pixels() > 0 && ray.pixel >= h.pixels())
    return fmt::format("pixel {} is beyond the header's {} x {} grid", ray.pixel, h.width,
                       h.height);
  return {};
}

std::vector<uint8_t> encode_header(const StreamHeader& h) {
  std::vector<uint8_t> out(kStreamMagic, kStreamMagic + 8);
  ByteWriter w(out);
  w.put(kStreamVersion);
  w.put(uint32_t(0));  // header_bytes, patched below
  w.put(h.scene_fingerprint);
  w.put(h.seed);
  w.put(h.frame_count);
  w.put(h.width);
  w.put(h.height);
  w.put(h.chunk_rays);
  for (auto c : h.counts) w.put(c);
  w.put_string(h.scene_source);
  w.put_string(h.workload);
  w.put_string(h.generator);
  encode_instance_settings(h.instances, out);
  auto total = static_cast<uint32_t>(out.size() + 4);
  std::memcpy(out.data() + 12, &total, 4);
  w.put(crc32(out.data(), out.size()));
  return out;
}

void encode_instance_settings(const InstanceSettings& s, std::vector<uint8_t>& out) {
  ByteWriter w(out);
  auto put_vec = [&](const glm::vec3& v) {
    for (int i = 0; i < 3; ++i) w.put(v[i]);
  };
  for (uint8_t m : s.ray_masks) w.put(m);
  w.put(uint32_t(s.masks.size()));
  for (const auto& [instance, mask] : s.masks) {
    w.put(instance);
    w.put(mask);
  }
  w.put(uint32_t(s.motions.size()));
  for (const Motion& m : s.motions) {
    put_vec(m.axis);
    w.put(uint32_t(m.keys.size()));
    for (const MotionKey& k : m.keys) {
      put_vec(k.translate);
      w.put(k.rotate);
      w.put(k.scale);
    }
  }
  w.put(uint32_t(s.moving.size()));
  for (const auto& [instance, motion] : s.moving) {
    w.put(instance);
    w.put(motion);
  }
}

bool decode_instance_settings(ByteReader& in, InstanceSettings& s) {
  auto get_vec = [&] {
    glm::vec3 v;
    for (int i = 0; i < 3; ++i) v[i] = in.get<float>();
    return v;
  };
  // A count is trusted only as far as the bytes left could hold it.
  auto count = [&](size_t item_bytes) {
    auto n = in.get<uint32_t>();
    if (in.ok() && n > in.left() / item_bytes) in.fail();
    return in.ok() ? n : 0;
  };
  for (uint8_t& m : s.ray_masks) m = in.get<uint8_t>();
  s.masks.resize(count(5));
  for (auto& [instance, mask] : s.masks) {
    instance = in.get<uint32_t>();
    mask = in.get<uint8_t>();
  }
  s.motions.resize(count(16));
  for (Motion& m : s.motions) {
    m.axis = get_vec();
    m.keys.resize(count(20));
    for (MotionKey& k : m.keys) {
      k.translate = get_vec();
      k.rotate = in.get<float>();
      k.scale = in.get<float>();
    }
  }
  s.moving.resize(count(8));
  for (auto& [instance, motion] : s.moving) {
    instance = in.get<uint32_t>();
    motion = in.get<uint32_t>();
  }
  return in.ok();
}

void encode_ray(const Ray& r, std::vector<uint8_t>& out) {
  ByteWriter w(out);
  for (int i = 0; i < 3; ++i) w.put(r.org[i]);
  for (int i = 0; i < 3; ++i) w.put(r.dir[i]);
  w.put(r.tmin);
  w.put(r.tmax);
  w.put(r.pixel);
  w.put(r.frame);
  w.put(r.sample);
  w.put(static_cast<uint8_t>(r.type));
  w.put(uint8_t(uint8_t(r.query) | (r.force_opaque ? kForceOpaqueBit : 0)));
}

Ray decode_ray(const uint8_t* record) {
  ByteReader in(record, kRayRecordBytes);
  Ray r;
  for (int i = 0; i < 3; ++i) r.org[i] = in.get<float>();
  for (int i = 0; i < 3; ++i) r.dir[i] = in.get<float>();
  r.tmin = in.get<float>();
  r.tmax = in.get<float>();
  r.pixel = in.get<uint32_t>();
  r.frame = in.get<uint32_t>();
  r.sample = in.get<uint16_t>();
  r.type = static_cast<RayType>(in.get<uint8_t>());
  auto query = in.get<uint8_t>();
  r.force_opaque = (query & kForceOpaqueBit) != 0;
  r.query = static_cast<Query>(query & ~kForceOpaqueBit);  // other bits: ray_problem names them
  return r;
}

}  // namespace rtsim
