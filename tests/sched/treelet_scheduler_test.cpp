// The treelet queues alone, over a dispatcher: fresh rays, postponing, queue capacity, the
// scheduling policies and the min_batch rule, and when the supply is exhausted.
#include <gtest/gtest.h>

#include "model/sched/dispatcher.h"
#include "model/sched/treelet_scheduler.h"

namespace rtsim {
namespace {

struct Fixture {
  explicit Fixture(TreeletQueueConfig config, size_t rays = 8)
      : rays_(rays),
        source(rays_),
        pool(config.max_rays),
        dispatcher({100.0, 0}, source, pool, nullptr),
        queues(config, 16, {0}, dispatcher, pool, 100) {}
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

namespace rtsim {
namespace {

RayContext context(uint32_t id) {
  RayContext r;
  r.id = id;
  return r;
}

TEST(RayBuffer, EachBankMovesAStateAtItsPortsRateThenTheAccessLatency) {
  RayBufferConfig c;
  c.banks = 2;
  c.bytes_per_cycle = 32;
  c.latency = 4;
  RayBuffer buffer(c, 100, 8);  // 100 bytes: 4 cycles on a port
  RayContext a = context(0), b = context(1), d = context(2), e = context(4);
  EXPECT_EQ(buffer.store(a, 10), 17u) << "port cycles 10..13, then 4 of access";
  EXPECT_EQ(buffer.store(b, 10), 17u) << "bank 1 is free";
  EXPECT_EQ(buffer.store(d, 10), 21u) << "bank 0 is busy until 13";
  EXPECT_EQ(buffer.store(e, 5), 12u) << "an earlier request takes free earlier cycles";
  EXPECT_EQ(buffer.load(a, 30), 37u);
  EXPECT_EQ(buffer.stats().port_waits, 4u);
  EXPECT_EQ(buffer.stats().port_cycles, 20u);
  EXPECT_EQ(buffer.stats().sram_bytes, 500u);
  EXPECT_FALSE(a.state_in_memory);
}

TEST(RayBuffer, SpillPutsTheStatesBeyondTheSramInMemory) {
  RayBufferConfig c;
  c.bytes = 250;  // two states of 100 bytes
  c.overflow = RayBufferOverflow::Spill;
  RayBuffer buffer(c, 100, 8);
  EXPECT_EQ(buffer.capacity(), 2u);
  RayContext a = context(0), b = context(1), d = context(2);
  buffer.store(a, 0);
  buffer.store(b, 0);
  EXPECT_TRUE(buffer.accepts());
  EXPECT_EQ(buffer.store(d, 7), 7u) << "the unit writes it";
  EXPECT_TRUE(d.state_in_memory);
  EXPECT_EQ(buffer.load(d, 9), 9u) << "the unit reads it";
  EXPECT_EQ(buffer.stats().memory_writes, 1u);
  EXPECT_EQ(buffer.stats().memory_reads, 1u);
  EXPECT_EQ(buffer.stats().memory_bytes, 200u);
  EXPECT_EQ(buffer.stats().max_in_sram, 2u);
}

TEST(RayBuffer, InMemoryEveryStateGoesThroughTheUnits) {
  RayBufferConfig c;
  c.place = RayBufferPlace::Memory;
  RayBuffer buffer(c, 100, 8);
  EXPECT_EQ(buffer.capacity(), 0u);
  RayContext a = context(3);
  EXPECT_TRUE(buffer.admits_fresh());
  EXPECT_EQ(buffer.store(a, 5), 5u);
  EXPECT_TRUE(a.state_in_memory);
  EXPECT_NE(ray_state_address(3, 100), ray_state_address(4, 100));
  EXPECT_EQ(ray_state_address(4, 100) - ray_state_address(3, 100), 128u) << "whole lines";
}

TEST(TreeletScheduler, AFullRayBufferHoldsFreshRaysBackUntilAStateLeavesIt) {
  TreeletQueueConfig c = config("fullest", 8, 8);
  c.buffer.bytes = 200;  // two states of 100 bytes
  Fixture f(c);
  std::vector<RayContext*> fresh;
  ASSERT_EQ(f.queues.take(0, 0, 4, fresh), 4u);
  EXPECT_TRUE(f.queues.postpone(*fresh[0], 5, 10));
  EXPECT_TRUE(f.queues.postpone(*fresh[1], 5, 10));
  EXPECT_FALSE(f.queues.postpone(*fresh[2], 6, 11)) << "the SRAM is full: the ray goes on";
  EXPECT_EQ(f.queues.stats().refused, 1u);
  EXPECT_EQ(f.queues.buffer().stats().refused, 1u);
  std::vector<RayContext*> batch;
  ASSERT_EQ(f.queues.take(1, 20, 1, batch), 1u);
  EXPECT_EQ(batch[0], fresh[0]) << "fresh rays held back: the short queue is served";
  EXPECT_EQ(f.queues.buffer().stats().held, 1u);
  batch.clear();
  ASSERT_EQ(f.queues.take(1, 21, 1, batch), 1u);
  EXPECT_NE(batch[0], fresh[1]) << "a state left the SRAM: fresh rays come in again";
  EXPECT_EQ(f.queues.buffer().stats().held, 1u);
}

}  // namespace
}  // namespace rtsim
