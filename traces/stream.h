// The ray-stream file (.rays): header, chunked rays with checksums. Spec: traces/FORMAT.md.
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "traces/instance_settings.h"
#include "traces/output_file.h"
#include "traces/ray.h"

namespace rtsim {

constexpr uint32_t kStreamVersion = 2;  // also reads version 1 (no instance settings)
constexpr uint32_t kDefaultChunkRays = 16384;
constexpr uint32_t kMaxChunkRays = 1u << 20;
constexpr size_t kRayRecordBytes = 44;
// The largest pixel grid and frame count a stream may declare: those of `rtsim trace`
// (`--resolution` up to 65536 a side, so every pixel index fits the u32 field; `--frames` up
// to 100,000).
constexpr uint32_t kMaxGridSide = 65536;
constexpr uint32_t kMaxFrames = 100000;
// A grid may have at most this many pixels more than the stream has rays, so that buffers
// sized by the grid (sim's per-pixel buffers, 12 B a pixel) stay in proportion to the stream.
constexpr uint64_t kMaxGridPixelsBeyondRays = uint64_t(1) << 24;

struct StreamHeader {
  uint32_t version = kStreamVersion;  // as read (writers write kStreamVersion)
  std::string scene_source;           // scene file path, or "builtin:NAME[:PARAMS]"
  uint64_t scene_fingerprint = 0;
  std::string workload;
  std::string generator;  // program and version that wrote the stream
  uint64_t seed = 0;
  uint32_t frame_count = 1;
  uint32_t width = 0, height = 0;  // pixel grid that Ray::pixel indexes
  uint32_t chunk_rays = kDefaultChunkRays;
  std::array<uint64_t, kRayTypeCount> counts{};  // rays per RayType
  // The workload's masks and motion (settings.frames is frame_count).
  InstanceSettings instances;

  uint64_t total_rays() const;
  uint64_t pixels() const { return uint64_t(width) * height; }
};

// What is wrong with the header's frame count or grid (empty if nothing): frames beyond
// kMaxFrames, a side beyond kMaxGridSide, one side 0 and not the other (0 x 0: no grid).
std::string grid_problem(const StreamHeader& header);
// What places the ray outside the header (empty if nothing): a frame at or beyond frame_count,
// a pixel at or beyond width * height (unless the grid is 0 x 0).
std::string ray_outside_header(const Ray& ray, const StreamHeader& header);

// Writes to PATH.tmp-PID and renames to PATH in finish(); a writer destroyed before finish()
// removes its temporary file, so an interrupted run never leaves a half-written stream.
class RayStreamWriter {
 public:
  // Throws std::invalid_argument for a header that grid_problem() rejects.
  RayStreamWriter(const std::string& path, StreamHeader header);
  ~RayStreamWriter();
  RayStreamWriter(const RayStreamWriter&) = delete;
  RayStreamWriter& operator=(const RayStreamWriter&) = delete;

  // Throws std::invalid_argument for a ray that ray_problem() or ray_outside_header() rejects.
  void write(const Ray& ray);
  // InputError if the grid has more than kMaxGridPixelsBeyondRays pixels beyond the rays
  // written (readers would refuse the stream), or if the file cannot be written.
  void finish();
  const StreamHeader& header() const { return header_; }

 private:
  void flush_chunk();
  void write_bytes(const void* data, size_t size);

  std::string path_;
  OutputFile output_;
  StreamHeader header_;
  FILE* file_ = nullptr;
  std::vector<uint8_t> chunk_;
  uint32_t chunk_count_ = 0;
};

// Reads a stream chunk by chunk in constant memory. Every problem (bad magic, unsupported
// version, checksum mismatch, truncation, invalid ray, counts that disagree with the header)
// throws InputError naming the file and byte offset.
class RayStreamReader {
 public:
  explicit RayStreamReader(const std::string& path);
  // Reads from an open file (for example fmemopen), taking ownership; name is used in errors.
  RayStreamReader(FILE* file, const std::string& name);
  RayStreamReader(const RayStreamReader&) = delete;
  RayStreamReader& operator=(const RayStreamReader&) = delete;

  const StreamHeader& header() const { return header_; }
  const std::string& path() const { return path_; }
  // Next ray; false at the end of the stream (after checking the end marker and counts).
  bool next(Ray& ray);
  // Up to max rays appended to out (cleared first); returns how many.
  size_t next_batch(std::vector<Ray>& out, size_t max);
  uint64_t rays_read() const { return rays_read_; }

 private:
  void read_header();
  void check_counts_and_grid(size_t header_bytes);
  bool load_chunk();
  void read_exact(void* data, size_t size, uint64_t start, const char* what);
  [[noreturn]] void fail(uint64_t offset, const std::string& what) const;

  struct FileCloser {
    void operator()(FILE* f) const { std::fclose(f); }
  };
  std::string path_;
  std::unique_ptr<FILE, FileCloser> file_;
  StreamHeader header_;
  uint64_t offset_ = 0;
  std::vector<uint8_t> chunk_;
  uint64_t chunk_offset_ = 0;
  uint32_t chunk_size_ = 0, chunk_pos_ = 0;
  bool done_ = false;
  uint64_t rays_read_ = 0;
  std::array<uint64_t, kRayTypeCount> seen_{};
};

// Reads the whole stream; for tests and small streams.
std::vector<Ray> read_all_rays(const std::string& path, StreamHeader* header = nullptr);

}  // namespace rtsim
