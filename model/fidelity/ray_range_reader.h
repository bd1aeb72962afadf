// Reads chosen ranges of rays from a ray stream without reading the rest, for the sampled
// level: the header is read and checked by RayStreamReader, then the chunk layout of
// traces/FORMAT.md (u32 count, 44-byte records, u32 CRC) is indexed by seeking from chunk to
// chunk, and only the records asked for are read and decoded. Each ray read is checked as the
// stream reader checks it (ray_problem, known type and query); chunk CRCs are not, since that
// would mean reading every byte (`rtsim trace-info` checks a whole file).
// Records are decoded by traces/stream_codec.h; a RayStreamReader::seek(ray) that walks the
// chunk headers would replace the chunk index kept here.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "traces/stream.h"

namespace rtsim {

class RayRangeReader {
 public:
  explicit RayRangeReader(const std::string& path);  // InputError on a bad header or layout
  const StreamHeader& header() const { return header_; }
  uint64_t rays() const { return rays_; }
  // Appends rays [begin, end) (stream positions) to out.
  void read(uint64_t begin, uint64_t end, std::vector<Ray>& out);

 private:
  struct Chunk {
    uint64_t first_ray, offset, count;  // offset: of its first record
  };
  struct FileCloser {
    void operator()(FILE* f) const { std::fclose(f); }
  };
  std::string path_;
  std::unique_ptr<FILE, FileCloser> file_;
  StreamHeader header_;
  std::vector<Chunk> chunks_;
  uint64_t rays_ = 0;
  std::vector<uint8_t> buffer_;
};

}  // namespace rtsim
