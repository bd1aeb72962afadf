// Slot cycles per ray: a warp's hold (first dispatch to last retirement) is shared by its rays
// in per-ray mode; in treelet mode each ray holds its slot for its own latency.
#include <gtest/gtest.h>

#include "model/multi/slot_cost.h"
#include "model/sched/ray_context.h"

namespace rtsim::multi {
namespace {

HwConfig small_unit(TraversalMode mode) {
  HwConfig c;
  c.rt_units = 2;
  c.rt.warps = 2;
  c.rt.warp_size = 4;
  c.rt.mode = mode;
  return c;
}

void retire(SlotCostListener& l, uint32_t unit, uint32_t slot, uint32_t pixel, RayType type,
            Cycle dispatched, Cycle now) {
  RayContext ray;
  ray.ray.pixel = pixel;
  ray.ray.type = type;
  ray.unit = unit;
  ray.slot = slot;
  ray.dispatched = ray.handed = dispatched;  // as the dispatcher sets them
  l.retired(ray, now);
}

TEST(SlotCost, AWarpsHoldIsSharedByItsRays) {
  SlotCostListener l(small_unit(TraversalMode::DepthFirst), 10);
  // Unit 1, warp 1 (slots 4..7): four rays dispatched at 10..11, the last retires at 100.
  retire(l, 1, 4, 0, RayType::Camera, 10, 50);
  retire(l, 1, 5, 0, RayType::Shadow, 10, 80);
  retire(l, 1, 6, 1, RayType::Shadow, 11, 60);
  retire(l, 1, 7, 2, RayType::Camera, 11, 100);
  // The refill: dispatched at 100, after the warp emptied; it has two rays.
  retire(l, 1, 4, 3, RayType::DiffuseGI, 100, 130);
  retire(l, 1, 5, 3, RayType::DiffuseGI, 101, 160);
  // Unit 0, warp 0: one ray alone.
  retire(l, 0, 1, 9, RayType::AO, 5, 25);
  l.finish();
  const std::vector<double>& cost = l.pixel_cost();
  EXPECT_DOUBLE_EQ(cost[0], 2 * 90.0 / 4) << "two rays, each a quarter of a 90-cycle hold";
  EXPECT_DOUBLE_EQ(cost[1], 90.0 / 4);
  EXPECT_DOUBLE_EQ(cost[2], 90.0 / 4);
  EXPECT_DOUBLE_EQ(cost[3], 60.0) << "second fill: 100 to 160, two rays";
  EXPECT_DOUBLE_EQ(cost[9], 20.0);
  EXPECT_DOUBLE_EQ(l.type_rays()[size_t(RayType::Shadow)], 2.0);
  EXPECT_DOUBLE_EQ(l.type_cost()[size_t(RayType::DiffuseGI)], 60.0);
  double total = 0;
  for (double c : cost) total += c;
  EXPECT_DOUBLE_EQ(total, 90 + 60 + 20) << "the warps' holds, all of them";
}

TEST(SlotCost, TreeletModeChargesEachRayItsLatency) {
  SlotCostListener l(small_unit(TraversalMode::Treelet), 4);
  retire(l, 0, 0, 1, RayType::Camera, 10, 50);
  retire(l, 0, 1, 1, RayType::Camera, 10, 200);
  retire(l, 0, 2, 7, RayType::Shadow, 10, 30);  // outside the image: by type only
  l.finish();
  EXPECT_DOUBLE_EQ(l.pixel_cost()[1], 40 + 190);
  EXPECT_DOUBLE_EQ(l.type_cost()[size_t(RayType::Shadow)], 20);
}

}  // namespace
}  // namespace rtsim::multi
