// The per-unit event queue: earliest cycle first, insertion order within a cycle, also for
// events beyond the wheel; checked against a reference on a seeded random schedule.
#include <gtest/gtest.h>

#include <map>
#include <vector>

#include "model/sched/event_queue.h"

namespace rtsim {
namespace {

TEST(EventQueue, OrdersByCycleThenInsertion) {
  EventQueue q;
  q.push(10, 1);
  q.push(5, 2);
  q.push(10, 3);
  q.push(5 + 3 * EventQueue::kWheel, 4);  // far beyond the wheel
  q.push(7, 5);
  std::vector<std::pair<Cycle, uint32_t>> got;
  while (!q.empty()) {
    EventQueue::Event e = q.pop();
    got.push_back({e.cycle, e.item});
  }
  std::vector<std::pair<Cycle, uint32_t>> want = {
      {5, 2}, {7, 5}, {10, 1}, {10, 3}, {5 + 3 * EventQueue::kWheel, 4}};
  EXPECT_EQ(got, want);
}

TEST(EventQueue, MatchesReferenceOnRandomSchedule) {
  EventQueue q;
  std::map<Cycle, std::vector<uint32_t>> reference;  // per cycle, in insertion order
  uint64_t seed = 12345;
  auto next = [&] { return (seed = seed * 6364136223846793005ull + 1) >> 33; };
  Cycle now = 0;
  uint32_t item = 0;
  size_t popped = 0;
  for (int round = 0; round < 20000; ++round) {
    if (next() % 3 != 0 || q.empty()) {
      Cycle at = now + next() % (next() % 7 == 0 ? 5000 : 300);  // some far ones
      q.push(at, item);
      reference[at].push_back(item++);
      continue;
    }
    ASSERT_EQ(q.next_cycle(), reference.begin()->first) << "round " << round;
    EventQueue::Event e = q.pop();
    auto& bucket = reference.begin()->second;
    ASSERT_EQ(e.item, bucket.front()) << "FIFO within a cycle, round " << round;
    bucket.erase(bucket.begin());
    if (bucket.empty()) reference.erase(reference.begin());
    now = e.cycle;
    ++popped;
  }
  EXPECT_GT(popped, 5000u);
  EXPECT_EQ(q.size(), [&] {
    size_t n = 0;
    for (auto& [c, b] : reference) n += b.size();
    return n;
  }());
}

TEST(EventQueue, LookingAheadDoesNotForbidEarlierEvents) {
  // A unit looks at its next event (to sleep until then), then is woken earlier with new rays.
  EventQueue q;
  q.push(1000, 1);
  EXPECT_EQ(q.next_cycle(), 1000u);
  q.push(500, 2);
  EXPECT_EQ(q.next_cycle(), 500u);
  EXPECT_EQ(q.pop().item, 2u);
  EXPECT_EQ(q.pop().item, 1u);
}

TEST(EventQueue, RefusesThePast) {
  EventQueue q;
  q.push(100, 1);
  q.pop();
  EXPECT_THROW(q.push(99, 2), std::logic_error);
}

}  // namespace
}  // namespace rtsim
