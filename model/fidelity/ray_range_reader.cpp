#include "model/fidelity/ray_range_reader.h"

#include <algorithm>
#include <cstring>

#include "traces/error.h"
#include "traces/stream_codec.h"

namespace rtsim {
namespace {

template <typename T>
T load(const uint8_t* p) {
  T value;
  std::memcpy(&value, p, sizeof value);
  return value;
}

}  // namespace

RayRangeReader::RayRangeReader(const std::string& path) : path_(path) {
  header_ = RayStreamReader(path).header();
  file_.reset(std::fopen(path.c_str(), "rb"));
  if (!file_) throw_input_error(path, "", "cannot open");
  uint8_t word[4];
  if (std::fseek(file_.get(), 12, SEEK_SET) != 0 || std::fread(word, 4, 1, file_.get()) != 1)
    throw_input_error(path, "offset 12", "truncated header");
  uint64_t offset = load<uint32_t>(word);
  for (;;) {
    if (std::fseek(file_.get(), long(offset), SEEK_SET) != 0 ||
        std::fread(word, 4, 1, file_.get()) != 1)
      throw_input_error(path, "offset " + std::to_string(offset), "truncated before a chunk");
    uint64_t count = load<uint32_t>(word);
    if (count == 0) break;
    if (count > header_.chunk_rays)
      throw_input_error(path, "offset " + std::to_string(offset),
                        "chunk of " + std::to_string(count) + " rays exceeds chunk_rays");
    chunks_.push_back({rays_, offset + 4, count});
    rays_ += count;
    offset += 4 + kRayRecordBytes * count + 4;
  }
  if (rays_ != header_.total_rays())
    throw_input_error(path, "end marker",
                      "the chunks hold " + std::to_string(rays_) + " rays, the header counts " +
                          std::to_string(header_.total_rays()));
}

void RayRangeReader::read(uint64_t begin, uint64_t end, std::vector<Ray>& out) {
  end = std::min(end, rays_);
  auto it = std::upper_bound(chunks_.begin(), chunks_.end(), begin,
                             [](uint64_t r, const Chunk& c) { return r < c.first_ray; });
  for (--it; begin < end; ++it) {
    uint64_t first = begin - it->first_ray;
    uint64_t count = std::min(end - begin, it->count - first);
    uint64_t offset = it->offset + first * kRayRecordBytes;
    buffer_.resize(count * kRayRecordBytes);
    if (std::fseek(file_.get(), long(offset), SEEK_SET) != 0 ||
        std::fread(buffer_.data(), buffer_.size(), 1, file_.get()) != 1)
      throw_input_error(path_, "offset " + std::to_string(offset), "truncated");
    for (uint64_t i = 0; i < count; ++i) {
      const uint8_t* record = buffer_.data() + i * kRayRecordBytes;
      Ray ray = decode_ray(record);
      std::string problem = ray_problem(ray);
      if (!problem.empty())
        throw_input_error(path_, "offset " + std::to_string(offset + i * kRayRecordBytes), problem);
      out.push_back(ray);
    }
    begin += count;
  }
}

}  // namespace rtsim
