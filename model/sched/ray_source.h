// Where the dispatcher's rays come from: a ray stream read in constant memory, or a vector
// (benchmarks and tests).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "traces/stream.h"

namespace rtsim {

class RaySource {
public:
  virtual ~RaySource() = default;
  virtual bool next(Ray& ray) = 0;  // false at the end
};

class VectorRaySource : public RaySource {
public:
  explicit VectorRaySource(const std::vector<Ray>& rays) : rays_(rays) {}
  bool next(Ray& ray) override {
    if (position_ == rays_.size()) return false;
    ray = rays_[position_++];
    return true;
  }

private:
  const std::vector<Ray>& rays_;
  size_t position_ = 0;
};

// Reads a stream chunk by chunk; errors in the file throw InputError when reached.
class StreamRaySource : public RaySource {
public:
  explicit StreamRaySource(RayStreamReader& reader) : reader_(reader) {}
  bool next(Ray& ray) override { return reader_.next(ray); }

private:
  RayStreamReader& reader_;
};

}  // namespace rtsim
