#include "traces/stream.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fmt/core.h>

#include "traces/bytes.h"
#include "traces/error.h"
#include "traces/hash.h"
#include "traces/stream_codec.h"

namespace rtsim {

RayStreamWriter::RayStreamWriter(const std::string& path, StreamHeader header)
    : path_(path), output_(path), header_(std::move(header)) {
  if (header_.chunk_rays == 0 || header_.chunk_rays > kMaxChunkRays)
    throw std::invalid_argument("chunk_rays must be in [1, " + std::to_string(kMaxChunkRays) + "]");
  header_.counts = {};
  if (std::string problem = grid_problem(header_); !problem.empty())
    throw std::invalid_argument("stream header: " + problem);
  if (output_.sequential())  // checked before opening: opening a FIFO waits for a reader
    throw_input_error(path_, "",
                      "cannot write a ray stream to a FIFO or socket: it needs a "
                      "seekable file (its header is completed last)");
  file_ = std::fopen(output_.write_path().c_str(), "wb");
  if (!file_) throw_input_error(path_, "", std::string("cannot write: ") + std::strerror(errno));
  auto bytes = encode_header(header_);
  write_bytes(bytes.data(), bytes.size());
  chunk_.reserve(8 + size_t(header_.chunk_rays) * kRayRecordBytes);
}

RayStreamWriter::~RayStreamWriter() {
  if (file_) {
    std::fclose(file_);
    output_.discard();
  }
}

void RayStreamWriter::write(const Ray& ray) {
  if (!file_) throw std::logic_error("RayStreamWriter::write after finish");
  std::string problem = ray_problem(ray);
  if (problem.empty()) problem = ray_outside_header(ray, header_);
  if (!problem.empty()) throw std::invalid_argument("cannot write ray: " + problem);
  if (chunk_count_ == 0) chunk_.assign(4, 0);  // room for the count
  encode_ray(ray, chunk_);
  header_.counts[static_cast<int>(ray.type)]++;
  if (++chunk_count_ == header_.chunk_rays) flush_chunk();
}

void RayStreamWriter::flush_chunk() {
  if (chunk_count_ == 0) chunk_.assign(4, 0);
  std::memcpy(chunk_.data(), &chunk_count_, 4);
  uint32_t crc = crc32(chunk_.data(), chunk_.size());
  ByteWriter(chunk_).put(crc);
  write_bytes(chunk_.data(), chunk_.size());
  chunk_count_ = 0;
}

void RayStreamWriter::finish() {
  if (!file_) return;
  if (header_.pixels() > header_.total_rays() + kMaxGridPixelsBeyondRays)
    throw_input_error(
        path_, "",
        fmt::format("a {} x {} pixel grid for {} rays: readers refuse a grid of more "
                    "than {} pixels beyond its rays; trace a smaller resolution",
                    header_.width, header_.height, header_.total_rays(), kMaxGridPixelsBeyondRays));
  if (chunk_count_ > 0) flush_chunk();
  flush_chunk();  // an empty chunk marks the end
  auto bytes = encode_header(header_);
  if (std::fflush(file_) != 0)  // what is buffered fails here on a full disk, not in the seek
    throw_input_error(path_, "", std::string("cannot write: ") + std::strerror(errno));
  if (std::fseek(file_, 0, SEEK_SET) != 0)
    throw_input_error(path_, "", "cannot seek back to the header: a stream needs a seekable file");
  write_bytes(bytes.data(), bytes.size());
  bool ok = std::fflush(file_) == 0;
  if (output_.renames()) ok = ok && fsync(fileno(file_)) == 0;
  ok = std::fclose(file_) == 0 && ok;
  file_ = nullptr;
  if (!ok || !output_.commit()) {
    output_.discard();
    throw_input_error(path_, "", std::string("cannot write: ") + std::strerror(errno));
  }
}

void RayStreamWriter::write_bytes(const void* data, size_t size) {
  if (std::fwrite(data, 1, size, file_) != size)
    throw_input_error(path_, "", std::string("cannot write: ") + std::strerror(errno));
}

}  // namespace rtsim
