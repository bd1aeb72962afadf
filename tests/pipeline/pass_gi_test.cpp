// Diffuse GI: surfel spawning per tile, the per-frame budget, and light connections.
#include "workloads/pipeline/pass_gi.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "tests/pipeline/test_scenes.h"

namespace rtsim::pipeline {
namespace {

TEST(GiBudget, SplitsTheBudgetWithABoostForNewSurfels) {
  GiSpec spec;
  spec.rays_per_surfel = 10;
  spec.new_surfel_boost = 4.0f;
  spec.new_surfel_frames = 2;
  spec.budget = 1000000;
  std::vector<Surfel> surfels(3);
  surfels[0].born_frame = 0;
  surfels[1].born_frame = 5;
  surfels[2].born_frame = 6;
  std::vector<uint32_t> counts = gi_ray_counts(surfels, spec, 6);
  EXPECT_EQ(counts, (std::vector<uint32_t>{10, 40, 40}));  // under budget: as wanted
  spec.budget = 45;
  counts = gi_ray_counts(surfels, spec, 6);
  EXPECT_EQ(counts[0] + counts[1] + counts[2], 45u);  // capped exactly at the budget
  EXPECT_GT(counts[1], counts[0]);
  spec.budget = 2;  // fewer rays than surfels: one each to some, rotating with the frame
  EXPECT_EQ(gi_ray_counts(surfels, spec, 7)[0] + gi_ray_counts(surfels, spec, 7)[1] +
                gi_ray_counts(surfels, spec, 7)[2],
            2u);
}

struct GiRun {
  std::vector<Ray> gi, light;
  std::vector<uint32_t> gi_origins;
  GiOutcome outcome;
};

GiRun run(const test::Fixture& fx, SurfelCache& cache, uint32_t frame) {
  GiRun out;
  FrameContext f = fx.frame(frame);
  GBuffer g = fx.gbuffer(f);
  RaySink sink(nullptr, fx.spec.width, fx.spec.height, false);
  sink.observer = [&](const Ray& r, PassId pass, uint32_t origin) {
    if (pass == PassId::DiffuseGI) {
      out.gi.push_back(r);
      out.gi_origins.push_back(origin);
    } else {
      EXPECT_EQ(pass, PassId::GiLight);
      out.light.push_back(r);
    }
  };
  out.outcome = run_gi_pass(f, g, cache, sink);
  return out;
}

// A box open toward the camera: the wall at z = 0 and a ceiling at y = 2 over it, lit by a
// point light; surfels spawn on the wall and shoot cosine rays, some of which hit the ceiling.
Scene box_scene() {
  Scene s;
  test::add_wall(s, test::material("wall", 1.0f));
  test::add_quad(s, {-5, 2, 0}, {5, 2, 0}, {5, 2, 6}, {-5, 2, 6}, test::material("top", 1.0f),
                 "ceiling");
  return s;
}

TEST(GiPass, SpawnsAtMostOneSurfelPerTileAndUsesTheBudget) {
  test::Fixture fx(box_scene(), {test::point_light({0, 0, 3}, 50.0f)}, 64, 48);
  fx.spec.passes.gi.budget = 3000;
  SurfelCache cache(0.0f);
  GiRun first = run(fx, cache, 0);
  EXPECT_GT(first.outcome.spawned, 0u);
  EXPECT_LE(first.outcome.spawned, (64u / 16u) * (48u / 16u));
  EXPECT_GT(cache.radius(), 0.0f);
  uint64_t wanted = 0;
  for (uint32_t c : gi_ray_counts(cache.surfels(), fx.spec.passes.gi, 0)) wanted += c;
  EXPECT_EQ(first.gi.size(), std::min<uint64_t>(3000, wanted));
  for (size_t i = 0; i < first.gi.size(); ++i) {
    const Ray& r = first.gi[i];
    EXPECT_EQ(r.type, RayType::DiffuseGI);
    EXPECT_EQ(r.query, Query::ClosestHit);
    glm::vec3 n = first.gi_origins[i] < 2 ? glm::vec3(0, 0, 1) : glm::vec3(0, -1, 0);
    EXPECT_GE(glm::dot(r.dir, n), 0.0f) << "cosine hemisphere above the surfel";
  }
  // Light connections: shadow rays from GI hits, at most one per GI ray.
  EXPECT_GT(first.light.size(), 0u);
  EXPECT_LE(first.light.size(), first.gi.size());
  for (const Ray& r : first.light) {
    EXPECT_EQ(r.type, RayType::Shadow);
    EXPECT_EQ(r.query, Query::AnyHit);
  }
  // Later frames keep the surfels and fill holes; the budget still caps the rays.
  size_t before = cache.surfels().size();
  GiRun second = run(fx, cache, 1);
  EXPECT_GE(cache.surfels().size(), before);
  EXPECT_LE(second.gi.size(), 3000u);
}

TEST(GiPass, NothingToBounceWithoutLightsEmissionOrSky) {
  Scene s;
  test::add_wall(s, test::material("wall", 1.0f));
  test::Fixture fx(std::move(s), {});
  SurfelCache cache(0.0f);
  GiRun r = run(fx, cache, 0);
  EXPECT_TRUE(r.gi.empty());
  EXPECT_EQ(r.outcome.gi.skipped, "nothing to bounce: no lights, emission or sky");
}

TEST(Surfels, CoverageFallsOffWithDistanceAndNormal) {
  SurfelCache cache(1.0f);
  Surfel s;
  s.position = glm::vec3(0.0f);
  s.normal = glm::vec3(0, 0, 1);
  cache.add(s);
  EXPECT_NEAR(cache.coverage({0, 0, 0}, {0, 0, 1}), 1.0f, 1e-6f);
  EXPECT_GT(cache.coverage({0.5f, 0, 0}, {0, 0, 1}), 0.0f);
  EXPECT_LT(cache.coverage({0.5f, 0, 0}, {0, 0, 1}), 1.0f);
  EXPECT_EQ(cache.coverage({1.5f, 0, 0}, {0, 0, 1}), 0.0f);
  EXPECT_EQ(cache.coverage({0, 0, 0}, {0, 0, -1}), 0.0f);         // facing away
  EXPECT_EQ(cache.coverage({0, 0, 0.5f}, {0, 0, 1}), 0.0f);       // squashed along the normal
  EXPECT_GT(cache.coverage({-0.9f, -0.2f, 0}, {0, 0, 1}), 0.0f);  // found across grid cells
}

}  // namespace
}  // namespace rtsim::pipeline
