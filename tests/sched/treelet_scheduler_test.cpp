// The treelet queues alone, over a dispatcher: fresh rays, postponing, queue capacity, the
// scheduling policies and the min_batch rule, and when the supply is exhausted.
#include <gtest/gtest.h>

#include "model/sched/dispatcher.h"
#include "model/sched/treelet_scheduler.h"

namespace rtsim {
namespace {

struct Fixture {
  explicit Fixture(TreeletQueueConfig config, size_t rays = 8)
      : rays_(rays), source(rays_), pool(config.max_rays),
        dispatcher({100.0, 0}, source, pool, nullptr),
        queues(config, 16, 0, dispatcher, pool) {}
  std::vector<Ray> rays_;
  VectorRaySource source;
  RayContextPool pool;
  RayDispatcher dispatcher;
  TreeletScheduler queues;
};

TreeletQueueConfig config(const char* policy, uint32_t capacity, uint32_t min_batch) {
  TreeletQueueConfig c;
  c.policy = policy;
  c.max_rays = 8;
  c.queue_capacity = capacity;
  c.min_batch = min_batch;
  c.enqueue_latency = 3;
  c.dequeue_latency = 2;
  return c;
}

TEST(TreeletScheduler, PostponedRaysComeBackAsOneBatch) {
  Fixture f(config("fullest", 2, 2));
  std::vector<RayContext*> fresh;
  ASSERT_EQ(f.queues.take(0, 0, 4, fresh), 4u) << "no queue yet: fresh rays";
  EXPECT_EQ(fresh[0]->treelet, 0u) << "fresh rays start in the root treelet";
  EXPECT_TRUE(f.queues.postpone(*fresh[0], 5, 10));
  EXPECT_EQ(fresh[0]->ready, 13u) << "enqueue latency";
  EXPECT_TRUE(f.queues.postpone(*fresh[1], 5, 10));
  EXPECT_FALSE(f.queues.postpone(*fresh[2], 5, 10)) << "queue of 5 is full (capacity 2)";
  EXPECT_EQ(f.queues.stats().refused, 1u);
  EXPECT_TRUE(f.queues.postpone(*fresh[3], 7, 11));
  std::vector<RayContext*> batch;
  ASSERT_EQ(f.queues.take(1, 20, 4, batch), 2u) << "queue 5 holds min_batch: it goes first";
  EXPECT_EQ(batch[0], fresh[0]);
  EXPECT_EQ(batch[1], fresh[1]);
  EXPECT_EQ(batch[0]->treelet, 5u);
  EXPECT_EQ(batch[0]->ready, 22u) << "dequeue latency";
  EXPECT_EQ(f.queues.queued(), 1u);
  EXPECT_EQ(f.queues.stats().visits, 2u);
  EXPECT_EQ(f.queues.stats().visit_rays, 6u);
}

TEST(TreeletScheduler, ShortQueuesWaitWhileFreshRaysRemain) {
  Fixture f(config("fullest", 8, 3));
  std::vector<RayContext*> a;
  f.queues.take(0, 0, 2, a);
  f.queues.postpone(*a[0], 9, 1);
  std::vector<RayContext*> b;
  ASSERT_EQ(f.queues.take(0, 2, 2, b), 2u);
  EXPECT_NE(b[0], a[0]) << "1 ray < min_batch 3: fresh rays are admitted instead";
}

TEST(TreeletScheduler, OldestPolicyServesTheFirstQueueFilled) {
  Fixture f(config("oldest", 8, 1), 4);
  std::vector<RayContext*> r;
  f.queues.take(0, 0, 4, r);
  f.queues.postpone(*r[0], 3, 1);
  f.queues.postpone(*r[1], 6, 2);
  f.queues.postpone(*r[2], 6, 3);
  std::vector<RayContext*> batch;
  ASSERT_EQ(f.queues.take(0, 5, 4, batch), 1u);
  EXPECT_EQ(batch[0]->treelet, 3u) << "oldest: queue 3, though queue 6 is longer";
}

TEST(TreeletScheduler, ExhaustedOnlyWhenNothingIsLeftAnywhere) {
  Fixture f(config("fullest", 8, 1), 2);
  std::vector<RayContext*> r;
  f.queues.take(0, 0, 2, r);
  EXPECT_FALSE(f.queues.exhausted()) << "two rays executing";
  f.queues.postpone(*r[0], 4, 1);
  f.queues.retire(*r[1], 2);
  EXPECT_FALSE(f.queues.exhausted()) << "one ray queued";
  std::vector<RayContext*> last;
  ASSERT_EQ(f.queues.take(0, 3, 2, last), 1u);
  f.queues.retire(*last[0], 9);
  EXPECT_TRUE(f.queues.exhausted());
  f.queues.account(9);
  EXPECT_GT(f.queues.stats().queued_ray_cycles, 0.0);
}

}  // namespace
}  // namespace rtsim
