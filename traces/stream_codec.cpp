#include "traces/stream_codec.h"

#include <cstring>

#include "traces/bytes.h"
#include "traces/hash.h"

namespace rtsim {

uint64_t StreamHeader::total_rays() const {
  uint64_t total = 0;
  for (auto c : counts) total += c;
  return total;
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
  auto total = static_cast<uint32_t>(out.size() + 4);
  std::memcpy(out.data() + 12, &total, 4);
  w.put(crc32(out.data(), out.size()));
  return out;
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
  w.put(static_cast<uint8_t>(r.query));
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
  r.query = static_cast<Query>(in.get<uint8_t>());
  return r;
}

}  // namespace rtsim
