#include "model/sc/sim_progress.h"

#include <unistd.h>

#include <cstdint>
#include <string>

#include <fmt/core.h>

namespace rtsim {

SimProgress::SimProgress(uint64_t total, std::FILE* out)
    : total_(total), out_(out), tty_(isatty(fileno(out)) != 0), steps_(tty_ ? 100 : 10) {
  next_ = (total_ + steps_ - 1) / steps_;
}

void SimProgress::retired(const RayContext&, Cycle now) {
  if (total_ == 0 || ++retired_ < next_) return;
  uint64_t step = retired_ * steps_ / total_;
  show(now);
  next_ = step >= steps_ ? UINT64_MAX : ((step + 1) * total_ + steps_ - 1) / steps_;
}

void SimProgress::show(Cycle now) {
  double done = double(retired_) / double(total_);
  if (!tty_) {
    fmt::print(out_, "sim: {:3.0f}%  {} of {} rays, cycle {}\n", 100.0 * done, retired_, total_,
               now);
    return;
  }
  int filled = int(done * 30.0);
  fmt::print(out_, "\r[{:<30}] {:3.0f}%  {} of {} rays, cycle {}", std::string(filled, '#'),
             100.0 * done, retired_, total_, now);
  std::fflush(out_);
}

void SimProgress::finish() {
  if (tty_ && total_ > 0) fmt::print(out_, "\r{:<90}\r", "");
}

}  // namespace rtsim
