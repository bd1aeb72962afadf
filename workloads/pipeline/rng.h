// Deterministic random numbers for the passes: PCG32 (O'Neill 2014) seeded by hashing the
// workload seed with the indices of what is being sampled (frame, pass, pixel, ...), so every
// random decision depends only on those inputs, never on the order in which work is done.
// std:: distributions are not used: their output is implementation-defined.
#pragma once

#include <cstdint>

namespace rtsim::pipeline {

// SplitMix64 finaliser: a strong 64-bit mix used to derive seeds.
inline uint64_t mix64(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

inline uint64_t hash_combine(uint64_t a, uint64_t b) {
  return mix64(a ^ mix64(b));
}

// Identifies what a random stream is for, so two passes never share one.
enum class RngStream : uint32_t {
  CameraJitter = 1,
  SamplePlacement,
  CellChoice,
  Shadow,
  Reflection,
  ReflectionRotation,
  ReflectedShadow,
  SurfelSpawn,
  DiffuseGI,
  GiLight,
  AO,
  Refraction,
  Translucency,
};

class Pcg32 {
 public:
  explicit Pcg32(uint64_t seed, uint64_t stream = 0) {
    inc_ = (stream << 1u) | 1u;
    next();
    state_ += seed;
    next();
  }

  uint32_t next() {
    uint64_t old = state_;
    state_ = old * 6364136223846793005ull + inc_;
    auto xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    auto rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }

  // Uniform in [0, 1): the top 24 bits, so every value is exactly representable.
  float uniform() { return static_cast<float>(next() >> 8) * 0x1p-24f; }

  // Uniform integer in [0, n) by rejection (no modulo bias); n > 0.
  uint32_t below(uint32_t n) {
    uint32_t threshold = (0u - n) % n;
    for (;;) {
      uint32_t r = next();
      if (r >= threshold) return r % n;
    }
  }

 private:
  uint64_t state_ = 0, inc_ = 0;
};

// A generator for one item of one stream: (seed, stream, frame, item) fully determine it.
inline Pcg32 make_rng(uint64_t seed, RngStream stream, uint32_t frame, uint64_t item) {
  uint64_t s = hash_combine(hash_combine(seed, static_cast<uint64_t>(stream)), frame);
  return Pcg32(hash_combine(s, item), static_cast<uint64_t>(stream));
}

}  // namespace rtsim::pipeline
