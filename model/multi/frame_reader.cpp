#include "model/multi/frame_reader.h"

#include <fmt/format.h>

#include "traces/error.h"

namespace rtsim::multi {

bool FrameReader::next(FrameRays& out) {
  const StreamHeader& header = reader_.header();
  if (frame_ >= header.frame_count) return false;
  out.frame = frame_;
  out.rays.clear();
  for (;;) {
    Ray ray;
    if (pending_) {
      ray = *pending_;
      pending_.reset();
    } else if (ended_ || !reader_.next(ray)) {
      ended_ = true;
      break;
    }
    if (ray.frame < frame_)
      throw_input_error(
          reader_.path(), fmt::format("ray {}", reader_.rays_read() - 1),
          fmt::format("frame {} after frame {}: rays are not in frame order", ray.frame, frame_));
    if (ray.frame > frame_) {
      pending_ = ray;
      break;
    }
    out.rays.push_back(ray);
  }
  ++frame_;
  return true;
}

}  // namespace rtsim::multi
