// The on-chip traversal stack alone: what spills when a step pushes past the depth, and what a
// pop from an empty on-chip stack reads back.
#include <gtest/gtest.h>

#include <set>

#include "model/sched/hardware_stack.h"

namespace rtsim {
namespace {

TEST(HardwareStack, SpillsTheOldestEntriesPastTheDepth) {
  HardwareStack stack({4, 8}, 0);
  RayContext ray;
  ray.id = 3;
  stack.start(ray);
  // The root popped, 7 children pushed: 7 entries, 4 fit.
  StackTransfer spill = stack.settle(ray, 0, 7);
  EXPECT_EQ(spill.entries, 3u);
  EXPECT_EQ(spill.bytes, 24u);
  EXPECT_EQ(spill.addr, HardwareStack::region(3)) << "the ray's own region, from its bottom";
  EXPECT_EQ(ray.residency.resident, 4u);
  EXPECT_EQ(ray.residency.spilled, 3u);
  EXPECT_EQ(ray.cost.stack_spills, 3u);
}

TEST(HardwareStack, SlotRegionsBelongToTheSlotNotTheRay) {
  HardwareStack stack({4, 8}, 256);  // units of 256 ray slots
  RayContext first, next;
  first.id = 3;
  next.id = 9;
  for (RayContext* ray : {&first, &next}) {
    ray->unit = 2;
    ray->slot = 5;
    stack.start(*ray);
  }
  uint64_t slot_region = HardwareStack::region(2 * 256 + 5);
  EXPECT_EQ(stack.settle(first, 0, 7).addr, slot_region);
  EXPECT_EQ(stack.settle(next, 0, 7).addr, slot_region) << "the next ray in the slot reuses it";
}

TEST(HardwareStack, ARayMovedToAnotherLaneKeepsTheRegionItStartedIn) {
  HardwareStack stack({4, 8}, 256);
  RayContext ray;
  ray.unit = 2;
  ray.slot = 5;
  stack.start(ray);
  ray.slot = 9;  // packet reordering moved it
  StackTransfer spill = stack.settle(ray, 0, 7);
  EXPECT_EQ(spill.addr, HardwareStack::region(2 * 256 + 5));
  EXPECT_EQ(stack.refill(ray, 7).addr, spill.addr) << "read back from where it was written";
}

TEST(HardwareStack, RefillsExactlyWhatAPopNeeds) {
  HardwareStack stack({4, 8}, 0);
  RayContext ray;
  stack.start(ray);
  stack.settle(ray, 0, 7);  // 4 on chip, 3 spilled
  EXPECT_EQ(stack.refill(ray, 4).bytes, 0u) << "4 pops: all on chip";
  StackTransfer read = stack.refill(ray, 6);
  EXPECT_EQ(read.entries, 2u) << "6 pops with 4 on chip: two come back";
  EXPECT_EQ(read.addr, HardwareStack::region(0) + 1 * 8) << "the top two spilled entries";
  EXPECT_EQ(ray.residency.spilled, 1u);
  EXPECT_EQ(ray.cost.stack_refills, 2u);
}

TEST(HardwareStack, RegionsSpreadOverCacheSets) {
  // 1024 sets of 64-byte lines: the first line of 256 regions lands in 256 different sets.
  std::set<uint64_t> sets;
  for (uint32_t id = 0; id < 256; ++id) sets.insert(HardwareStack::region(id) / 64 % 1024);
  EXPECT_EQ(sets.size(), 256u);
}

TEST(HardwareStack, DeepStackNeverSpillsAndClearFreesAll) {
  HardwareStack stack({64, 8}, 0);
  RayContext ray;
  stack.start(ray);
  EXPECT_EQ(stack.settle(ray, 0, 40).bytes, 0u);
  stack.settle(ray, 39, 0);  // an any-hit query cleared its stack
  EXPECT_EQ(ray.residency.resident, 0u);
  EXPECT_EQ(ray.residency.spilled, 0u);
}

}  // namespace
}  // namespace rtsim
