#include "model/sched/ray_sorter.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rtsim {
namespace {

// Which of `steps` equal parts of [lo, hi] holds x; outside it, the nearest end part.
uint32_t quantise(double x, double lo, double hi, uint32_t steps) {
  if (!(hi > lo)) return 0;
  double part = std::floor((x - lo) / (hi - lo) * steps);
  return uint32_t(std::clamp(part, 0.0, double(steps - 1)));
}

uint64_t mix(uint64_t x) {  // splitmix64's finaliser
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

}  // namespace

const char* sort_key_name(SortKey key) {
  switch (key) {
    case SortKey::None: return "none";
    case SortKey::OctantCell: return "octant_cell";
    case SortKey::Hash: return "hash";
  }
  return "?";
}

std::string sort_config_problem(const SortConfig& c) {
  if (c.buffer_rays == 0 || c.buffer_rays > (1u << 24)) return "buffer_rays must be 1..16777216";
  if (c.grid == 0 || c.grid > 1024) return "grid must be 1..1024";
  if (c.direction_bins == 0 || c.direction_bins > 1024) return "direction_bins must be 1..1024";
  if (c.bins == 0 || c.bins > (1u << 24)) return "bins must be 1..16777216";
  if (c.key == SortKey::OctantCell && uint64_t(c.grid) * c.grid * c.grid * 8 > (1u << 24))
    return "grid: octant_cell keys need 8 * grid^3 <= 16777216 bins";
  return {};
}

CoherenceKey::CoherenceKey(const SortConfig& config, const SceneBounds& bounds)
    : config_(config),
      bounds_(bounds),
      bins_(config.key == SortKey::Hash ? config.bins
                                        : 8 * config.grid * config.grid * config.grid) {}

uint32_t CoherenceKey::octant(const glm::vec3& d) {
  return uint32_t(std::signbit(d.x)) | uint32_t(std::signbit(d.y)) << 1 |
         uint32_t(std::signbit(d.z)) << 2;
}

uint32_t CoherenceKey::origin_cell(const glm::vec3& o) const {
  uint32_t g = config_.grid;
  uint32_t x = quantise(o.x, bounds_.lo.x, bounds_.hi.x, g);
  uint32_t y = quantise(o.y, bounds_.lo.y, bounds_.hi.y, g);
  uint32_t z = quantise(o.z, bounds_.lo.z, bounds_.hi.z, g);
  return x + g * (y + g * z);
}

uint32_t CoherenceKey::operator()(const Ray& ray) const {
  uint32_t cell = origin_cell(ray.org);
  if (config_.key != SortKey::Hash) return cell * 8 + octant(ray.dir);
  double length = std::sqrt(double(ray.dir.x) * ray.dir.x + double(ray.dir.y) * ray.dir.y +
                            double(ray.dir.z) * ray.dir.z);
  uint64_t direction = 0;
  for (int axis = 0; axis < 3; ++axis) {
    double unit = length > 0 ? ray.dir[axis] / length : 0.0;
    direction =
        direction * config_.direction_bins + quantise(unit, -1.0, 1.0, config_.direction_bins);
  }
  return uint32_t(mix(uint64_t(cell) << 32 | direction) % config_.bins);
}

namespace {

const SortConfig& checked(const SortConfig& config) {
  std::string problem = sort_config_problem(config);
  if (problem.empty() && config.key == SortKey::None) problem = "key none: no sorting unit";
  if (!problem.empty()) throw std::invalid_argument(problem);
  return config;
}

}  // namespace

RaySorter::RaySorter(const SortConfig& config, const SceneBounds& bounds, RaySupply& upstream)
    : config_(checked(config)),
      key_(config, bounds),
      upstream_(upstream),
      fullest_(make_treelet_policy("fullest", key_.bins())),
      bins_(key_.bins()) {}

void RaySorter::set_length(uint32_t bin, uint32_t length) {
  fullest_->changed(bin, bins_[bin].length, length);
  bins_[bin].length = length;
}

void RaySorter::fill(uint32_t unit, Cycle now) {
  if (held_ >= config_.buffer_rays || upstream_.exhausted()) return;
  arrivals_.clear();
  upstream_.take(unit, now, config_.buffer_rays - held_, arrivals_);
  for (RayContext* ray : arrivals_) on_the_way_.push(ray);
  held_ += uint32_t(arrivals_.size());
  stats_.max_held = std::max<uint64_t>(stats_.max_held, held_);
}

void RaySorter::admit(Cycle at) {
  while (on_the_way_.head && on_the_way_.head->ready <= at) {
    RayContext* ray = on_the_way_.pop();
    uint32_t b = key_(ray->ray);
    RayFifo& bin = bins_[b];
    if (!bin.head) by_head_.insert({ray->sequence, b});
    bin.push(ray);
    set_length(b, bin.length + 1);
    binned_++;
    newest_ = ray->sequence;
  }
}

size_t RaySorter::serve(uint32_t b, Cycle at, size_t max, std::vector<RayContext*>& out) {
  RayFifo& bin = bins_[b];
  by_head_.erase({bin.head->sequence, b});
  size_t given = 0;
  while (given < max && bin.head) {
    RayContext* ray = bin.pop();
    Cycle leave = std::max(at, ray->ready) + config_.latency;
    stats_.wait_cycles += leave - ray->ready;
    ray->handed = std::max(at, ray->ready);
    ray->ready = leave;
    if (watcher_) watcher_(*ray);  // before it counts as handed out
    stats_.rays++;
    out.push_back(ray);
    ++given;
  }
  if (bin.head) by_head_.insert({bin.head->sequence, b});
  set_length(b, bin.length - uint32_t(given));
  held_ -= uint32_t(given);
  binned_ -= uint32_t(given);
  stats_.bins_served++;
  return given;
}

size_t RaySorter::take(uint32_t unit, Cycle now, size_t max, std::vector<RayContext*>& out) {
  fill(unit, now);
  size_t want = std::min<size_t>(max, held_);
  if (want == 0) return 0;
  // The group forms once `want` rays are in the buffer.
  Cycle at = now;
  const RayContext* ray = on_the_way_.head;
  for (size_t count = binned_; count < want; ++count, ray = ray->next_in_queue)
    at = std::max(at, ray->ready);
  admit(at);
  size_t given = 0;
  uint64_t max_age = uint64_t(config_.max_age) * config_.buffer_rays;
  if (max_age > 0 && !by_head_.empty()) {
    auto [sequence, oldest] = *by_head_.begin();
    if (newest_ - sequence >= max_age) {
      stats_.aged++;
      given += serve(oldest, at, max, out);
    }
  }
  while (given < max) {
    std::optional<uint32_t> pick = fullest_->pick();
    if (!pick) break;
    given += serve(*pick, at, max - given, out);
  }
  stats_.takes++;
  return given;
}

}  // namespace rtsim
