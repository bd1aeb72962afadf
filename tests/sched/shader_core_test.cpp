// The shader side of an RT unit alone (model/sched/shader_core.h), between a dispatcher and a
// mock L1, with the unit played by the test: exact cycles of ray generation, the trace call's
// hand-off, shading after the slowest ray, shading reads and warp slots.
#include <gtest/gtest.h>

#include "model/sched/dispatcher.h"
#include "model/sched/shader_core.h"
#include "tests/sched/mock_neighbours.h"

namespace rtsim {
namespace {

struct Rig {
  explicit Rig(std::vector<Ray> rays_in, ShaderConfig config, Cycle memory_latency = 10,
               bool deferred = false)
      : rays(std::move(rays_in)),
        source(rays),
        pool(64),
        dispatcher({1000.0, 0}, source, pool, nullptr),
        memory(memory_latency, deferred),
        shader(config, dispatcher, memory, [this](Cycle at) { wakes.push_back(at); }) {}

  std::vector<RayContext*> take(Cycle now, size_t max) {
    std::vector<RayContext*> out;
    shader.take(0, now, max, out);
    return out;
  }
  void retire(RayContext* ray, Cycle now, bool hit) {
    ray->state.prim = hit ? 7 : kNoHit;
    shader.retire(*ray, now);
  }

  std::vector<Ray> rays;
  VectorRaySource source;
  RayContextPool pool;
  RayDispatcher dispatcher;
  test::MockRayMemory memory;
  std::vector<Cycle> wakes;
  ShaderCore shader;
};

std::vector<Ray> rays_of(std::vector<RayType> types) {
  std::vector<Ray> rays(types.size());
  for (size_t i = 0; i < rays.size(); ++i) {
    rays[i].type = types[i];
    rays[i].pixel = uint32_t(100 + i);
  }
  return rays;
}

ShaderConfig one_warp() {
  ShaderConfig c;
  c.model = ShaderModel::Simt;
  c.warps = 1;
  c.schedulers = 1;
  c.trace_latency = 20;
  c.bytes_per_hit = 64;
  c.cycles[int(RayType::Camera)] = {30, 150, 25};
  c.cycles[int(RayType::Shadow)] = {40, 0, 10};
  return c;
}

TEST(ShaderCore, RaysReachTheUnitAfterRayGenerationAndTheHandOff) {
  Rig rig(rays_of({RayType::Camera, RayType::Camera, RayType::Camera, RayType::Camera}),
          one_warp());
  std::vector<RayContext*> warp = rig.take(100, 3);
  ASSERT_EQ(warp.size(), 3u);
  for (RayContext* ray : warp) EXPECT_EQ(ray->ready, 100u + 30 + 20);
  EXPECT_EQ(rig.shader.stats().raygen_cycles, 30u) << "one warp, one ray type: one raygen";
  EXPECT_EQ(rig.shader.stats().trace_delay_cycles, 3u * 50);
  EXPECT_TRUE(rig.take(100, 4).empty()) << "the SM's only warp slot is tracing";
  EXPECT_TRUE(rig.wakes.empty()) << "no slot's end is known yet";
  EXPECT_EQ(rig.shader.stats().slot_waits, 1u);
}

TEST(ShaderCore, DivergingRayTypesRunEachRayGeneration) {
  Rig rig(rays_of({RayType::Camera, RayType::Shadow}), one_warp());
  std::vector<RayContext*> warp = rig.take(0, 4);
  ASSERT_EQ(warp.size(), 2u);
  EXPECT_EQ(warp[0]->ready, 30u + 40 + 20);
  EXPECT_EQ(rig.shader.stats().type_cycles[int(RayType::Shadow)], 40u);
}

TEST(ShaderCore, AWarpShadesAfterItsSlowestRayAndFreesItsSlotAfterwards) {
  std::vector<Ray> rays = rays_of({RayType::Camera, RayType::Camera, RayType::Camera});
  rays.push_back(rays[0]);  // a second warp's ray
  Rig rig(rays, one_warp());
  std::vector<RayContext*> warp = rig.take(0, 3);
  ASSERT_EQ(warp.size(), 3u);
  rig.retire(warp[0], 200, false);
  rig.retire(warp[1], 210, true);
  EXPECT_TRUE(rig.memory.reads.empty()) << "shading waits for the warp's last ray";
  rig.retire(warp[2], 260, false);
  // Shading starts a hand-off after the last ray: hit and miss shaders both run (SIMT).
  Cycle shaded = 260 + 20 + 150 + 25;
  ASSERT_EQ(rig.memory.reads.size(), 1u) << "one hit: one shading read";
  EXPECT_EQ(rig.memory.reads[0].addr, kShadingBase + 101 * 64) << "at the hit ray's pixel";
  EXPECT_EQ(rig.memory.reads[0].bytes, 64u);
  EXPECT_EQ(rig.memory.reads[0].at, 260u);
  EXPECT_EQ(rig.shader.stats().hit_cycles, 150u);
  EXPECT_EQ(rig.shader.stats().miss_cycles, 25u);
  EXPECT_EQ(rig.shader.next_wake(260), kPending) << "nobody waits";
  EXPECT_TRUE(rig.take(shaded - 1, 3).empty());
  ASSERT_FALSE(rig.wakes.empty());
  EXPECT_EQ(rig.wakes.back(), shaded) << "the waiting unit is woken when the slot frees";
  EXPECT_EQ(rig.shader.next_wake(shaded - 1), shaded) << "what the stall watchdog waits for";
  EXPECT_EQ(rig.take(shaded, 3).size(), 1u);
  EXPECT_EQ(rig.shader.stats().slot_wait_cycles, 1u);
  EXPECT_EQ(rig.shader.next_wake(shaded), kPending);
}

TEST(ShaderCore, TheLastWarpsShadingIsWhatTheWatchdogWaitsFor) {
  Rig rig(rays_of({RayType::Camera}), one_warp());
  std::vector<RayContext*> warp = rig.take(0, 1);
  ASSERT_EQ(warp.size(), 1u);
  rig.retire(warp[0], 200, false);  // the stream's last ray: the unit waits for its shading
  Cycle shaded = 200 + 20 + 25;     // the hand-off, then miss shading
  EXPECT_EQ(rig.shader.next_wake(201), shaded) << "no stall while the last warp shades";
  EXPECT_EQ(rig.shader.next_wake(shaded + 1), kPending) << "nothing left";
}

TEST(ShaderCore, AWarpWithNoShaderWorkDoesNotWaitForAScheduler) {
  Rig rig(rays_of({RayType::Shadow}), one_warp());
  std::vector<RayContext*> warp = rig.take(0, 1);
  EXPECT_EQ(warp[0]->ready, 40u + 20) << "raygen holds the only scheduler until 40";
  rig.retire(warp[0], 5, true);  // a shadow hit: no hit shader (0 cycles)
  EXPECT_EQ(rig.shader.stats().last_cycle, 5u + 20) << "freed after the hand-off, not at 40";
}

TEST(ShaderCore, ShadingReadsHoldTheSlotUntilTheirDataIsBack) {
  ShaderConfig c = one_warp();
  c.bytes_per_hit = 200;
  Rig rig(rays_of({RayType::Camera, RayType::Camera}), c, 1000, true);
  std::vector<RayContext*> warp = rig.take(0, 2);
  rig.retire(warp[0], 100, true);
  rig.retire(warp[1], 100, true);
  ASSERT_EQ(rig.memory.reads.size(), 2u);
  EXPECT_EQ(rig.memory.reads[1].addr - rig.memory.reads[0].addr, 200u) << "neighbour pixels";
  EXPECT_EQ(rig.shader.stats().read_bytes, 400u);
  EXPECT_FALSE(rig.shader.exhausted()) << "the stream is done but the reads are not back";
  EXPECT_TRUE(rig.take(500, 2).empty());
  rig.memory.answer_all();  // the data at 100 + 1000, after the shading's 100 + 20 + 150
  EXPECT_TRUE(rig.shader.exhausted());
  EXPECT_EQ(rig.shader.stats().last_cycle, 1100u);
  EXPECT_EQ(rig.wakes.back(), 1100u);
}

TEST(ShaderCore, WarpsShareTheSchedulers) {
  ShaderConfig c = one_warp();
  c.warps = 2;
  Rig rig(rays_of({RayType::Camera, RayType::Camera}), c);
  std::vector<RayContext*> first = rig.take(0, 1), second = rig.take(0, 1);
  ASSERT_EQ(second.size(), 1u);
  EXPECT_EQ(first[0]->ready, 50u);
  EXPECT_EQ(second[0]->ready, 80u) << "the second warp's raygen waits for the first's";
}

TEST(ShaderCore, EachFrameShadesNewData) {
  EXPECT_EQ(shading_address(0, 3, 64), kShadingBase + 3 * 64);
  EXPECT_NE(shading_address(1, 3, 64), shading_address(0, 3, 64));
  for (uint32_t frame : {1u, 77u, 100000u}) {
    for (uint32_t bytes : {96u, 65536u}) {
      uint64_t addr = shading_address(frame, 0xffffffffu, bytes);
      EXPECT_GE(addr, kShadingBase);
      EXPECT_LE(addr + bytes, kTextureBase) << "never reaches the textures";
    }
  }
}

TEST(ShaderCore, AnSmWithoutSchedulersIsRefused) {
  ShaderConfig c = one_warp();
  c.schedulers = 0;
  EXPECT_NE(shader_config_problem(c), "");
  EXPECT_EQ(shader_config_problem(one_warp()), "");
}

}  // namespace
}  // namespace rtsim
