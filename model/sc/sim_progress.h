// Progress of a long simulation on stderr, driven by retired rays: a bar redrawn in place on
// a terminal, otherwise a line at every tenth of the stream (logs stay short). Says nothing
// about the results, so it never changes an output file.
#pragma once

#include <cstdint>
#include <cstdio>

#include "model/sched/ray_supply.h"

namespace rtsim {

class SimProgress : public RayRetireListener {
 public:
  // total: rays in the stream (0: unknown, then nothing is printed).
  SimProgress(uint64_t total, std::FILE* out = stderr);
  void retired(const RayContext& ray, Cycle now) override;
  // Clears the bar (on a terminal); call when the run ends.
  void finish();

 private:
  void show(Cycle now);

  uint64_t total_, retired_ = 0, next_ = 0;
  std::FILE* out_;
  bool tty_;
  uint32_t steps_;  // updates over the whole stream
};

}  // namespace rtsim
