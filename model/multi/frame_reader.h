// The rays of a stream one frame at a time, in constant memory per frame. Frames come in
// order 0, 1, ..., frame_count - 1 (a frame without rays comes as an empty one); a stream
// whose rays are not in frame order is an InputError naming the file.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "traces/stream.h"

namespace rtsim::multi {

struct FrameRays {
  uint32_t frame = 0;
  std::vector<Ray> rays;
};

class FrameReader {
 public:
  explicit FrameReader(RayStreamReader& reader) : reader_(reader) {}
  // The next frame; false after the last.
  bool next(FrameRays& out);

 private:
  RayStreamReader& reader_;
  uint32_t frame_ = 0;
  std::optional<Ray> pending_;  // the first ray of the next frame, read ahead
  bool ended_ = false;
};

}  // namespace rtsim::multi
