// The ray sorting unit with a mock dispatcher upstream: its keys at their edges, which rays a
// take gets, when they reach the unit (to the cycle), aging, its buffer bound and the flush at
// the stream's end.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "model/sched/ray_sorter.h"
#include "tests/model/model_test_util.h"
#include "tests/sched/mock_neighbours.h"

namespace rtsim {
namespace {

const SceneBounds kBounds{glm::vec3(0.0f), glm::vec3(4.0f)};

SortConfig octant_cell(uint32_t buffer, uint32_t latency) {
  SortConfig c;
  c.key = SortKey::OctantCell;
  c.buffer_rays = buffer;
  c.latency = latency;
  c.grid = 4;
  c.max_age = 0;
  return c;
}

Ray ray_at(glm::vec3 origin, glm::vec3 dir) {
  Ray r;
  r.org = origin;
  r.dir = dir;
  return r;
}

TEST(CoherenceKey, OctantBitsAreTheNegativeComponentsAndMinusZeroCountsAsNegative) {
  EXPECT_EQ(CoherenceKey::octant({1, 1, 1}), 0u);
  EXPECT_EQ(CoherenceKey::octant({-1, 1, 1}), 1u);
  EXPECT_EQ(CoherenceKey::octant({1, -1, 1}), 2u);
  EXPECT_EQ(CoherenceKey::octant({1, 1, -1}), 4u);
  EXPECT_EQ(CoherenceKey::octant({-0.0f, 0.0f, -1}), 5u);
}

TEST(CoherenceKey, OriginCellsSplitTheBoundsEvenlyAndClampOutside) {
  CoherenceKey key(octant_cell(64, 0), kBounds);
  EXPECT_EQ(key.bins(), 8u * 64);
  EXPECT_EQ(key.origin_cell({0, 0, 0}), 0u);
  EXPECT_EQ(key.origin_cell({0.999f, 0.999f, 0.999f}), 0u);
  EXPECT_EQ(key.origin_cell({1, 0, 0}), 1u) << "a cell boundary belongs to the upper cell";
  EXPECT_EQ(key.origin_cell({0, 1, 0}), 4u);
  EXPECT_EQ(key.origin_cell({0, 0, 1}), 16u);
  EXPECT_EQ(key.origin_cell({4, 4, 4}), 63u) << "the upper bound is in the last cell";
  EXPECT_EQ(key.origin_cell({-100, 2.5f, 1e30f}), 0u + 4 * 2 + 16 * 3) << "outside: clamped";
  CoherenceKey flat(octant_cell(64, 0), {glm::vec3(0.0f), glm::vec3(4.0f, 4.0f, 0.0f)});
  EXPECT_EQ(flat.origin_cell({3, 3, 7}), 15u) << "a flat scene's axis has one cell";
  EXPECT_EQ(key(ray_at({1, 0, 0}, {-1, 0, 0})), 1u * 8 + 1);
}

TEST(CoherenceKey, HashKeepsLikeRaysTogetherWithinItsBins) {
  SortConfig c = octant_cell(64, 0);
  c.key = SortKey::Hash;
  c.bins = 37;
  c.direction_bins = 4;
  CoherenceKey key(c, kBounds);
  EXPECT_EQ(key.bins(), 37u);
  std::set<uint32_t> seen;
  for (int i = 0; i < 200; ++i) {
    float a = 0.1f * float(i);
    uint32_t bin = key(ray_at({a, 2, 1}, {std::cos(a), std::sin(a), 0.3f}));
    EXPECT_LT(bin, 37u);
    seen.insert(bin);
  }
  EXPECT_GT(seen.size(), 8u) << "different origins and directions spread over the bins";
  EXPECT_EQ(key(ray_at({1.1f, 2, 3}, {0.5f, 0.5f, 0.5f})),
            key(ray_at({1.2f, 2.1f, 3.1f}, {2.1f, 2, 2})))
      << "same cell, same quantised unit direction (the length does not matter)";
}

const TraversalUnit& any_traversal() {  // the mock's listener needs one; no ray retires here
  static TriangleMesh mesh = test::random_soup(10, 0.5f, 1);
  static BvhImage image = build_bvh_image(mesh, BvhConfig{});
  static TraversalUnit unit(image);
  return unit;
}

// Two keys interleaved: even rays go +x, odd rays -x, all from one cell.
struct Interleaved {
  explicit Interleaved(size_t count) {
    for (size_t i = 0; i < count; ++i)
      rays.push_back(ray_at({0.5f, 0.5f, 0.5f}, {i % 2 ? -1.f : 1.f, 0.1f, 0.1f}));
    supply =
        std::make_unique<test::MockSupply>(rays, any_traversal(), 4096, DispatchConfig{1.0, 0});
  }
  std::vector<Ray> rays;
  std::unique_ptr<test::MockSupply> supply;
};

TEST(RaySorter, TheFirstGroupFormsOnceEnoughRaysHaveArrivedFromThoseThereBy) {
  Interleaved in(16);  // the dispatcher brings one ray a cycle, no latency
  RaySorter sorter(octant_cell(8, 3), kBounds, in.supply->dispatcher);
  std::vector<RayContext*> out;
  // The buffer asks for 8 rays at 100: they arrive at 100..107. A group of 4 forms at 103, when
  // rays 0..3 are there: both bins hold 2, the lower (+x) goes first, then the other.
  ASSERT_EQ(sorter.take(0, 100, 4, out), 4u);
  std::vector<uint64_t> order;
  for (RayContext* ray : out) {
    order.push_back(ray->sequence);
    EXPECT_EQ(ray->ready, 103u + 3) << "formed at 103, then the sorter's latency";
    EXPECT_EQ(ray->handed, 103u);
  }
  EXPECT_EQ(order, (std::vector<uint64_t>{0, 2, 1, 3}));
  EXPECT_EQ(sorter.stats().wait_cycles, 6u + 4 + 5 + 3) << "leaving - arrival";
  EXPECT_EQ(sorter.held(), 4u) << "rays 4..7 on their way";
}

TEST(RaySorter, ATakeGetsOneKeysRaysLatencyAfterTheTake) {
  Interleaved in(16);
  RaySorter sorter(octant_cell(8, 3), kBounds, in.supply->dispatcher);
  std::vector<RayContext*> out;
  ASSERT_EQ(sorter.take(0, 0, 1, out), 1u);  // fills the buffer: rays 0..7 arrive at 0..7
  EXPECT_EQ(out[0]->sequence, 0u);
  EXPECT_EQ(out[0]->ready, 3u);
  out.clear();
  // At 100 ray 8 tops the buffer up (arriving at 100); bins +x: 2, 4, 6, 8 and -x: 1, 3, 5, 7.
  ASSERT_EQ(sorter.take(0, 100, 4, out), 4u);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(out[i]->sequence, 2 * i + 2);
    EXPECT_EQ(out[i]->ready, 103u);
  }
  EXPECT_EQ(sorter.held(), 4u);
  EXPECT_EQ(sorter.stats().max_held, 8u) << "never more than buffer_rays";
  EXPECT_EQ(in.supply->dispatcher.stats().rays, 9u) << "the dispatcher filled it, no more";
}

TEST(RaySorter, ATakeLargerThanABinDrawsOnTheNextFullestBins) {
  Interleaved in(6);
  RaySorter sorter(octant_cell(6, 0), kBounds, in.supply->dispatcher);
  std::vector<RayContext*> out;
  ASSERT_EQ(sorter.take(0, 0, 5, out), 5u);
  EXPECT_EQ(out[0]->sequence, 0u);
  EXPECT_EQ(out[2]->sequence, 4u);
  EXPECT_EQ(out[3]->sequence, 1u) << "then the other bin, oldest first";
  EXPECT_EQ(sorter.stats().bins_served, 2u);
}

TEST(RaySorter, AnOverlookedRayIsServedOnceMaxAgeBuffersOfLaterRaysReachedTheBuffer) {
  // Ray 0 goes -y; every later ray goes +y, so "fullest" alone would leave ray 0 waiting.
  Interleaved in(0);
  in.rays.push_back(ray_at({0.5f, 0.5f, 0.5f}, {0, -1, 0}));
  for (int i = 0; i < 40; ++i) in.rays.push_back(ray_at({0.5f, 0.5f, 0.5f}, {0, 1, 0}));
  in.supply = std::make_unique<test::MockSupply>(in.rays, any_traversal(), 4096);
  SortConfig c = octant_cell(8, 0);
  c.max_age = 2;  // 16 rays
  RaySorter sorter(c, kBounds, in.supply->dispatcher);
  std::vector<RayContext*> out;
  std::vector<uint64_t> order;
  while (sorter.take(0, 0, 2, out) > 0) {
    for (RayContext* ray : out) order.push_back(ray->sequence);
    out.clear();
  }
  // Takes of 2 keep 8 rays: the first brings rays 0..7, each later one two more; the sixth
  // brings 16 and 17, and 16 - 0 >= 16: it serves ray 0 first.
  ASSERT_EQ(order.size(), 41u);
  EXPECT_EQ(order[9], 10u);
  EXPECT_EQ(order[10], 0u);
  EXPECT_EQ(sorter.stats().aged, 1u);
  EXPECT_TRUE(sorter.exhausted()) << "the stream's end flushes every bin";
  EXPECT_EQ(sorter.held(), 0u);
}

TEST(RaySorter, AKeyOfNoneOrABadBufferIsRefused) {
  Interleaved in(1);
  SortConfig c = octant_cell(8, 0);
  c.key = SortKey::None;
  EXPECT_THROW(RaySorter(c, kBounds, in.supply->dispatcher), std::invalid_argument);
  c = octant_cell(0, 0);
  EXPECT_NE(sort_config_problem(c), "");
}

}  // namespace
}  // namespace rtsim
