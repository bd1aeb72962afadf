#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <limits>

#include <fmt/core.h>

#include "traces/bytes.h"
#include "traces/error.h"
#include "traces/hash.h"
#include "traces/stream.h"
#include "traces/stream_codec.h"

namespace rtsim {

RayStreamReader::RayStreamReader(const std::string& path) : path_(path) {
  file_.reset(std::fopen(path.c_str(), "rb"));
  if (!file_) throw_input_error(path, "", std::string("cannot open: ") + std::strerror(errno));
  read_header();
}

RayStreamReader::RayStreamReader(FILE* file, const std::string& name) : path_(name), file_(file) {
  read_header();
}

void RayStreamReader::read_header() {
  std::vector<uint8_t> head(kHeaderFixedBytes);
  read_exact(head.data(), 16, 0, "header");
  if (std::memcmp(head.data(), kStreamMagic, 8) != 0)
    fail(0, "not an rtsim ray stream (bad magic)");
  uint32_t version, header_bytes;
  std::memcpy(&version, head.data() + 8, 4);
  std::memcpy(&header_bytes, head.data() + 12, 4);
  if (version != 1 && version != kStreamVersion)
    fail(8, "stream version " + std::to_string(version) +
                " is not supported (this rtsim reads 1 to " + std::to_string(kStreamVersion) + ")");
  if (header_bytes < kHeaderFixedBytes + 16 || header_bytes > kMaxHeaderBytes)
    fail(12, "header size " + std::to_string(header_bytes) + " is out of range");
  head.resize(header_bytes);
  read_exact(head.data() + 16, header_bytes - 16, 12, "header of the size at this offset");
  uint32_t stored_crc;
  std::memcpy(&stored_crc, head.data() + header_bytes - 4, 4);
  if (crc32(head.data(), header_bytes - 4) != stored_crc)
    fail(0, "header checksum mismatch (header bytes 0 to " + std::to_string(header_bytes) + ")");

  header_.version = version;
  ByteReader in(head.data() + 16, header_bytes - 20);
  header_.scene_fingerprint = in.get<uint64_t>();
  header_.seed = in.get<uint64_t>();
  header_.frame_count = in.get<uint32_t>();
  header_.width = in.get<uint32_t>();
  header_.height = in.get<uint32_t>();
  header_.chunk_rays = in.get<uint32_t>();
  for (auto& c : header_.counts) c = in.get<uint64_t>();
  header_.scene_source = in.get_string();
  header_.workload = in.get_string();
  header_.generator = in.get_string();
  size_t settings_at = 16 + in.pos();
  if (version >= 2 && !decode_instance_settings(in, header_.instances))
    fail(settings_at, "instance settings do not fit the header size");
  if (!in.ok() || in.pos() != header_bytes - 20)
    fail(16, "header fields do not fit the header size");
  header_.instances.frames = header_.frame_count;
  if (std::string problem = settings_problem(header_.instances, kNoHit); !problem.empty())
    fail(settings_at, "instance settings: " + problem);
  if (header_.chunk_rays == 0 || header_.chunk_rays > kMaxChunkRays)
    fail(44, "chunk size " + std::to_string(header_.chunk_rays) + " is out of range");
  check_counts_and_grid(header_bytes);
  chunk_.resize(4 + size_t(header_.chunk_rays) * kRayRecordBytes + 4);
}

// Before anything is sized by them: the counts must fit the file (a regular file's size bounds
// its rays), and the grid and frames must keep within their maxima and in proportion to the
// rays (traces/FORMAT.md).
void RayStreamReader::check_counts_and_grid(size_t header_bytes) {
  uint64_t room = std::numeric_limits<uint64_t>::max();
  struct stat info {};
  int fd = fileno(file_.get());
  if (fd >= 0 && fstat(fd, &info) == 0 && S_ISREG(info.st_mode))
    room =
        (uint64_t(info.st_size) - std::min<uint64_t>(info.st_size, header_bytes)) / kRayRecordBytes;
  uint64_t total = 0;
  for (int t = 0; t < kRayTypeCount; ++t) {
    if (header_.counts[t] > room - total)
      fail(48 + 8 * t, fmt::format("header counts {} {} rays, more than the file's {} bytes "
                                   "can hold",
                                   header_.counts[t], ray_type_name(RayType(t)), info.st_size));
    total += header_.counts[t];
  }
  std::string problem = grid_problem(header_);
  if (!problem.empty()) fail(header_.frame_count > kMaxFrames ? 32 : 36, problem);
  if (header_.pixels() > total + kMaxGridPixelsBeyondRays)
    fail(36, fmt::format("pixel grid {} x {} has {} pixels, more than {} beyond the stream's {} "
                         "rays",
                         header_.width, header_.height, header_.pixels(), kMaxGridPixelsBeyondRays,
                         total));
}

void RayStreamReader::fail(uint64_t offset, const std::string& what) const {
  throw_input_error(path_, "offset " + std::to_string(offset), what);
}

void RayStreamReader::read_exact(void* data, size_t size, uint64_t start, const char* what) {
  size_t got = std::fread(data, 1, size, file_.get());
  if (got != size)
    fail(start, std::string("file is truncated inside the ") + what + " (it ends at offset " +
                    std::to_string(offset_ + got) + ")");
  offset_ += size;
}

bool RayStreamReader::load_chunk() {
  chunk_offset_ = offset_;
  uint32_t count;
  read_exact(&count, 4, chunk_offset_, "chunk header");
  if (count > header_.chunk_rays)
    fail(chunk_offset_, "chunk of " + std::to_string(count) + " rays exceeds the chunk size " +
                            std::to_string(header_.chunk_rays));
  std::memcpy(chunk_.data(), &count, 4);
  size_t body = size_t(count) * kRayRecordBytes;
  read_exact(chunk_.data() + 4, body + 4, chunk_offset_, count ? "chunk" : "end marker");
  uint32_t stored_crc;
  std::memcpy(&stored_crc, chunk_.data() + 4 + body, 4);
  if (crc32(chunk_.data(), 4 + body) != stored_crc) fail(chunk_offset_, "chunk checksum mismatch");
  chunk_size_ = count;
  chunk_pos_ = 0;
  if (count > 0) return true;

  if (std::fgetc(file_.get()) != EOF) fail(offset_, "unexpected bytes after the end marker");
  for (int t = 0; t < kRayTypeCount; ++t)
    if (seen_[t] != header_.counts[t])
      fail(48 + 8 * t, std::string("header counts ") + std::to_string(header_.counts[t]) + " " +
                           ray_type_name(RayType(t)) + " rays, the stream holds " +
                           std::to_string(seen_[t]));
  done_ = true;
  return false;
}

bool RayStreamReader::next(Ray& ray) {
  if (done_) return false;
  if (chunk_pos_ == chunk_size_ && !load_chunk()) return false;
  const uint8_t* record = chunk_.data() + 4 + size_t(chunk_pos_) * kRayRecordBytes;
  ray = decode_ray(record);
  std::string problem = ray_problem(ray);
  if (problem.empty()) problem = ray_outside_header(ray, header_);
  if (!problem.empty())
    fail(chunk_offset_ + 4 + uint64_t(chunk_pos_) * kRayRecordBytes,
         "ray " + std::to_string(rays_read_) + ": " + problem);
  ++chunk_pos_;
  ++rays_read_;
  seen_[static_cast<int>(ray.type)]++;
  return true;
}

size_t RayStreamReader::next_batch(std::vector<Ray>& out, size_t max) {
  out.clear();
  Ray ray;
  while (out.size() < max && next(ray)) out.push_back(ray);
  return out.size();
}

std::vector<Ray> read_all_rays(const std::string& path, StreamHeader* header) {
  RayStreamReader reader(path);
  if (header) *header = reader.header();
  std::vector<Ray> rays;
  rays.reserve(std::min<uint64_t>(reader.header().total_rays(), 1u << 24));
  Ray ray;
  while (reader.next(ray)) rays.push_back(ray);
  return rays;
}

}  // namespace rtsim
