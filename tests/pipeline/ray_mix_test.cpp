// The ray mix at another resolution than the 1080p one the budgets are set for: diffuse GI keeps
// its fixed budget a frame, and the summary and the note say what that makes of the mix.
#include <gtest/gtest.h>

#include <string>

#include "traces/embree_scene.h"
#include "workloads/pipeline/pipeline.h"
#include "workloads/pipeline/summary.h"

namespace rtsim::pipeline {
namespace {

// The budgets of cornell.toml (one light, the ceiling quad) at w x h; nothing is traced.
RunSummary budgets(uint32_t w, uint32_t h, bool gi = true) {
  WorkloadSpec spec = read_spec(std::string(RTSIM_SOURCE_DIR) + "/workloads/specs/cornell.toml");
  spec.width = w;
  spec.height = h;
  spec.passes.gi.enabled = gi;
  Scene scene = load_scene(spec.scene);
  EmbreeScene embree(scene.mesh, 1);
  return Pipeline(spec, scene, embree).summary();
}

TEST(RayMix, AQuarterOf1080pHasSixteenTimesTheGiRaysAPixelAndSaysSo) {
  RunSummary s = budgets(480, 270);
  const PassSummary& gi = s.passes[size_t(PassId::DiffuseGI)];
  EXPECT_EQ(gi.budget, 250000u) << "the workload keeps its ray counts";
  EXPECT_NEAR(gi.budget_per_pixel_1080p, 250000.0 / (1920 * 1080), 1e-12);
  EXPECT_NEAR(s.passes[size_t(PassId::Camera)].budget_per_pixel_1080p, 1.0, 1e-12);
  EXPECT_NEAR(s.passes[size_t(PassId::AO)].budget_per_pixel_1080p, 0.25, 1e-12);
  std::string note = ray_mix_note(s);
  EXPECT_EQ(note.rfind("ray mix at 480x270 is not the 1920x1080 one the budgets are set for: ", 0),
            0u)
      << note;
  EXPECT_NE(note.find("diffuse_gi 1.93 against 0.121 (16x), gi_light 1.93 against 0.121 (16x);"),
            std::string::npos)
      << note;
  EXPECT_NE(note.find("gi.budget = 15625 keeps the 1920x1080 mix"), std::string::npos) << note;
  EXPECT_EQ(note.find("camera "), std::string::npos) << "per-pixel passes keep the mix: " << note;
  EXPECT_EQ(note.find("ao "), std::string::npos) << note;
  std::string table = format_summary(s);
  EXPECT_NE(table.find("1080p budget"), std::string::npos) << table;
  EXPECT_NE(table.find("1.9290       0.1206"), std::string::npos) << table;
}

TEST(RayMix, FourKHasAQuarterOfTheGiRaysAPixel) {
  std::string note = ray_mix_note(budgets(3840, 2160));
  EXPECT_NE(note.find("diffuse_gi 0.0301 against 0.121 (0.25x)"), std::string::npos) << note;
  EXPECT_NE(note.find("gi.budget = 1000000 keeps"), std::string::npos) << note;
}

TEST(RayMix, At1080pOrWithoutGiTheMixIsTheBudgetsOwn) {
  EXPECT_EQ(ray_mix_note(budgets(1920, 1080)), "");
  EXPECT_EQ(ray_mix_note(budgets(480, 270, false)), "");
}

}  // namespace
}  // namespace rtsim::pipeline
