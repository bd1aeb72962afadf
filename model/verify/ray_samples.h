// Seeded ray sets for verification and benchmarks while no pipeline stream is at hand:
// diffuse-GI-like rays (cosine-distributed from random surface points), pinhole camera rays
// and uniformly random rays. Deterministic: same mesh, count and seed, same rays everywhere.
#pragma once

#include <cstdint>
#include <vector>

#include "traces/instances.h"
#include "traces/ray.h"

namespace rtsim {

// Small portable generator (SplitMix64): identical sequences on every platform.
class SeededRandom {
 public:
  explicit SeededRandom(uint64_t seed) : state_(seed) {}
  uint64_t next();
  float uniform();  // in [0, 1), 24 random bits
 private:
  uint64_t state_;
};

// Rays leaving random surface points (area-weighted) on a random side, cosine-distributed
// about the normal, origin nudged off the surface; closest-hit, tmax = +inf, type DiffuseGI.
// triangles: a flat mesh, or a scene's instances without a flattened copy.
std::vector<Ray> sample_diffuse_rays(const FlatTriangles& triangles, size_t count, uint64_t seed);

// A width x height pinhole camera outside the triangles' bounds looking at their center, from
// `distance` times the bounds' half diagonal along (0.3, 0.4, 1) (nearer: the geometry fills more
// of the frame).
std::vector<Ray> sample_camera_rays(const FlatTriangles& triangles, uint32_t width, uint32_t height,
                                    float distance = 1.6f);

// Origins uniform in the triangles' bounds (grown by `margin` of the diagonal), directions
// uniform.
std::vector<Ray> sample_random_rays(const FlatTriangles& triangles, size_t count, uint64_t seed,
                                    float margin = 0.1f);

// Uniformly distributed unit vector.
glm::vec3 random_direction(SeededRandom& random);

}  // namespace rtsim
