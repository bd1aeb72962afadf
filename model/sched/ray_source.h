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

// A set of ray types, a bit per RayType.
using RayTypeMask = uint32_t;
constexpr RayTypeMask kAllRayTypes = (1u << kRayTypeCount) - 1;
inline RayTypeMask ray_type_bit(RayType type) {
  return 1u << unsigned(type);
}

// Reads a stream chunk by chunk, passing on the rays of the given types (all by default);
// errors in the file throw InputError when reached.
class StreamRaySource : public RaySource {
 public:
  explicit StreamRaySource(RayStreamReader& reader, RayTypeMask types = kAllRayTypes)
      : reader_(reader), types_(types) {}
  bool next(Ray& ray) override {
    while (reader_.next(ray))
      if (types_ & ray_type_bit(ray.type)) return true;
    return false;
  }

 private:
  RayStreamReader& reader_;
  RayTypeMask types_;
};

}  // namespace rtsim
