#include "model/mem/mini_cache.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "model/mem/slice_hash.h"

namespace rtsim {

namespace {

uint64_t full_sets(const CacheConfig& full) {
  return full.size_bytes / (uint64_t(full.line_bytes) * full.ways);
}

// splitmix64's finaliser: a hash of the line unrelated to the slice hash and the set bits.
uint64_t mix(uint64_t x) {
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

}  // namespace

std::string mini_cache_problem(const CacheConfig& full, uint32_t slices, uint32_t rate) {
  std::string problem = cache_config_problem(full);
  if (!problem.empty()) return problem;
  uint64_t sets = full_sets(full);
  if (rate < 1) return "a miniature needs a rate of 1 or more";
  if (slices < 1 || sets % slices != 0) return "the sets do not divide over the slices";
  if (sets % rate != 0)
    return "its " + std::to_string(sets) + " sets do not divide by the rate " +
           std::to_string(rate);
  return {};
}

MiniCache::MiniCache(const CacheConfig& full, uint32_t slices, uint32_t rate)
    : rate_(rate), line_shift_(uint32_t(__builtin_ctz(full.line_bytes))) {
  std::string problem = mini_cache_problem(full, slices, rate);
  if (!problem.empty()) throw std::invalid_argument("miniature cache: " + problem);
  uint64_t sets = full_sets(full) / rate;  // over all its slices
  uint64_t per_slice = std::max<uint64_t>(1, sets / slices);
  CacheConfig c = full;  // no ports, banks or MSHR limits: it counts, it does not time
  c.size_bytes = per_slice * full.line_bytes * full.ways;
  c.mshrs = 1;
  c.merge_limit = 0;
  c.banks = 1;
  c.bank_ports = 0;
  c.bytes_per_cycle = 0;
  for (uint64_t i = 0; i < sets / per_slice; ++i)
    slices_.push_back(std::make_unique<Cache>(c, &below_));
}

bool MiniCache::sampled(uint64_t line, uint32_t rate) {
  return rate <= 1 || (mix(line) >> 32) % rate == 0;
}

void MiniCache::reference(uint64_t addr, bool write) {
  uint64_t line = addr >> line_shift_;
  if (!sampled(line, rate_)) return;
  Cache& slice = *slices_[slice_of_line(line, uint32_t(slices_.size()))];
  now_ += 1 << 16;  // every reference finds the previous one's miss complete
  if (write) {
    slice.write(addr, slice.block_bytes(), now_);
    lines_[line];  // a line only written still counts as a sampled cluster
  } else {
    slice.read(addr, slice.block_bytes(), now_);
    lines_[line].reads++;
  }
}

Cycle MiniCache::Counter::read(uint64_t addr, uint32_t, Cycle at, ReadClient*, uint64_t,
                               ReadCharge&) {
  cache.lines_[addr >> cache.line_shift_].misses++;
  return at;
}

void MiniCache::Counter::write(uint64_t addr, uint32_t, Cycle) {
  cache.lines_[addr >> cache.line_shift_].writebacks++;
}

CacheStats MiniCache::stats() const {
  CacheStats sum;
  for (const auto& slice : slices_) sum += slice->stats();
  return sum;
}

MiniEstimate MiniCache::estimate(bool with_writebacks) const {
  // Integer sums, so the result does not depend on the map's order.
  uint64_t n = lines_.size(), sx = 0, sy = 0;
  long double sxx = 0, sxy = 0, syy = 0;
  for (const auto& [line, c] : lines_) {
    uint64_t y = c.misses + (with_writebacks ? c.writebacks : 0);
    sx += c.reads;
    sy += y;
    sxx += (long double)(c.reads * c.reads);
    sxy += (long double)(c.reads * y);
    syy += (long double)(y * y);
  }
  if (sx == 0) return {};
  long double r = (long double)sy / sx;
  long double ss = n > 1 ? (syy - 2 * r * sxy + r * r * sxx) / (n - 1) : 0;
  long double variance =
      (1 - 1.0L / rate_) * std::max<long double>(ss, 0) * n / ((long double)sx * sx);
  return {double(r), double(1.96L * std::sqrt(variance))};
}

}  // namespace rtsim
