#include "model/sched/treelet_scheduler.h"

#include <algorithm>
#include <stdexcept>

namespace rtsim {

std::string treelet_queue_config_problem(const TreeletQueueConfig& c) {
  if (!make_treelet_policy(c.policy, 1))
    return "policy '" + c.policy + "' is unknown (fullest, oldest)";
  if (c.max_rays == 0 || c.max_rays > (1u << 24)) return "max_rays must be 1..16777216";
  if (c.queue_capacity == 0) return "queue_capacity must be at least 1";
  if (c.min_batch == 0) return "min_batch must be at least 1";
  return ray_buffer_config_problem(c.buffer);
}

TreeletScheduler::TreeletScheduler(const TreeletQueueConfig& config, uint32_t treelets,
                                   std::vector<uint32_t> root_treelets, RaySupply& upstream,
                                   const RayContextPool& pool, uint32_t state_bytes)
    : config_(config),
      roots_(std::move(root_treelets)),
      upstream_(upstream),
      pool_(pool),
      policy_(make_treelet_policy(config.policy, treelets)),
      queues_(treelets),
      buffer_(config.buffer, state_bytes, config.max_rays) {
  std::string problem = treelet_queue_config_problem(config);
  if (!problem.empty()) throw std::invalid_argument(problem);
}

void TreeletScheduler::account(Cycle now) {
  if (now <= stats_.last_change) return;  // units may report slightly out of order
  stats_.queued_ray_cycles += double(queued_) * double(now - stats_.last_change);
  stats_.last_change = now;
}

void TreeletScheduler::set_length(uint32_t treelet, uint32_t length) {
  RayFifo& q = queues_[treelet];
  policy_->changed(treelet, q.length, length);
  q.length = length;
  stats_.max_queue_length = std::max<uint64_t>(stats_.max_queue_length, length);
}

size_t TreeletScheduler::take(uint32_t unit, Cycle now, size_t max, std::vector<RayContext*>& out) {
  account(now);
  std::optional<uint32_t> pick = policy_->pick();
  if (pick && queues_[*pick].length >= config_.min_batch) return serve(*pick, now, max, out);
  size_t room = pool_.capacity() - pool_.in_use();
  if (room > 0 && !upstream_.exhausted() && buffer_.admits_fresh()) {
    size_t first = out.size();
    size_t given = upstream_.take(unit, now, std::min(max, room), out);
    for (size_t i = first; i < out.size(); ++i)
      out[i]->treelet = roots_[std::min<size_t>(out[i]->ray.frame, roots_.size() - 1)];
    if (given > 0) {
      executing_ += given;
      stats_.visits++;
      stats_.fresh_visits++;
      stats_.visit_rays += given;
      return given;
    }
  }
  return pick ? serve(*pick, now, max, out) : 0;
}

size_t TreeletScheduler::serve(uint32_t treelet, Cycle now, size_t max,
                               std::vector<RayContext*>& out) {
  RayFifo& q = queues_[treelet];
  size_t given = 0;
  while (given < max && q.head) {
    RayContext* ray = q.pop();
    ray->treelet = treelet;
    ray->ready = std::max({ray->ready, now + config_.dequeue_latency, buffer_.load(*ray, now)});
    out.push_back(ray);
    ++given;
  }
  set_length(treelet, q.length - uint32_t(given));
  queued_ -= given;
  executing_ += given;
  stats_.visits++;
  stats_.visit_rays += given;
  return given;
}

bool TreeletScheduler::postpone(RayContext& ray, uint32_t treelet, Cycle now) {
  RayFifo& q = queues_[treelet];
  if (q.length >= config_.queue_capacity || !buffer_.accepts()) {
    stats_.refused++;
    return false;
  }
  account(now);
  ray.ready = std::max(now + config_.enqueue_latency, buffer_.store(ray, now));
  ray.cost.postponed++;
  q.push(&ray);
  set_length(treelet, q.length + 1);
  queued_++;
  executing_--;
  stats_.postponed++;
  stats_.max_queued = std::max(stats_.max_queued, queued_);
  return true;
}

void TreeletScheduler::retire(RayContext& ray, Cycle now) {
  account(now);
  executing_--;
  upstream_.retire(ray, now);
}

bool TreeletScheduler::exhausted() const {
  return queued_ == 0 && executing_ == 0 && upstream_.exhausted();
}

}  // namespace rtsim
