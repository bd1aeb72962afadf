// rtsim trace and bench-trace as a user runs them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "tests/cli/run_rtsim.h"
#include "traces/stream.h"

namespace rtsim {
namespace {

using test::run_rtsim;

std::string tmp(const std::string& name) {
  return ::testing::TempDir() + "cli-trace-" + name;
}

std::string spec(const std::string& name) {
  return std::string(RTSIM_SOURCE_DIR) + "/workloads/specs/" + name + ".toml";
}

TEST(CliTrace, WritesTheStreamWithOverridesAndASummary) {
  std::string out = tmp("cornell.rays");
  auto r = run_rtsim("trace " + spec("cornell") + " -o " + out +
                     " --resolution 64x48 --frames 2 --seed 5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  StreamHeader h;
  std::vector<Ray> rays = read_all_rays(out, &h);
  EXPECT_EQ(h.width, 64u);
  EXPECT_EQ(h.height, 48u);
  EXPECT_EQ(h.frame_count, 2u);
  EXPECT_EQ(h.seed, 5u);
  EXPECT_EQ(h.workload, "cornell");
  EXPECT_EQ(h.scene_source, "builtin:cornell");
  EXPECT_EQ(h.counts[size_t(RayType::Camera)], 2u * 64u * 48u);
  EXPECT_EQ(h.counts[size_t(RayType::Refraction)], 0u);
  EXPECT_NE(r.out.find("skipped: no transmissive surface in view"), std::string::npos) << r.out;
  // Not a terminal: plain progress lines, one per pass and frame.
  EXPECT_NE(r.err.find("trace: frame 2/2: ao"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\r'), std::string::npos);
  // 64x48 keeps GI's 250,000 rays a frame: another mix than 1080p's, and a line says so.
  EXPECT_NE(r.err.find("trace: ray mix at 64x48 is not the 1920x1080 one the budgets are set "
                       "for: budget rays a pixel diffuse_gi 81.4 against 0.121 (675x)"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("gi.budget = 370 keeps the 1920x1080 mix\n"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("1080p budget"), std::string::npos) << r.out;
  EXPECT_EQ(r.err.find("fitted"), std::string::npos) << "the spec places the camera: " << r.err;
  std::remove(out.c_str());
}

// A camera fitted to the scene: one line says where it stands and why (workloads/README.md).
TEST(CliTrace, AFittedCameraSaysWhereItStandsAndWhy) {
  std::string out = tmp("fitted.rays");
  auto object = run_rtsim("trace grid:512 --resolution 32x18 -o " + out);
  ASSERT_EQ(object.exit_code, 0) << object.err;
  size_t at = object.err.find("trace: camera fitted to the scene: at (");
  ASSERT_NE(at, std::string::npos) << object.err;
  EXPECT_EQ(object.err.find("trace: camera fitted", at + 1), std::string::npos) << object.err;
  EXPECT_NE(object.err.find("an object, not an enclosure", at), std::string::npos) << object.err;
  auto room = run_rtsim("trace cornell --resolution 32x18 -o " + out);
  ASSERT_EQ(room.exit_code, 0) << room.err;
  EXPECT_NE(room.err.find("trace: camera fitted to the scene: at ("), std::string::npos)
      << room.err;
  EXPECT_NE(room.err.find("an enclosure open on one side"), std::string::npos) << room.err;
  auto half = run_rtsim("trace grid:512 --resolution 32x18 --camera 40,20,40 -o " + out);
  EXPECT_NE(half.err.find("trace: camera look-at point fitted to the scene: at (40, 20, 40)"),
            std::string::npos)
      << half.err;
  std::remove(out.c_str());
}

// Moving and masked instances (city-traffic.toml: cars drive, trees cast no shadows): the stream
// records the settings, and the simulator rebuilds the top level per frame and agrees with
// Embree on every ray.
TEST(CliTrace, MovingAndMaskedInstancesTraceSimulateAndVerify) {
  std::string out = tmp("traffic.rays"), json = tmp("traffic.json");
  auto r = run_rtsim("trace " + spec("city-traffic") + " -q -o " + out +
                     " --resolution 96x54 --frames 3");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  RayStreamReader reader(out);
  const InstanceSettings& s = reader.header().instances;
  EXPECT_EQ(s.frames, 3u);
  EXPECT_EQ(s.motions.size(), 1u);
  EXPECT_GT(s.moving.size(), 10u) << "the cars";
  EXPECT_GT(s.masks.size(), 10u) << "the trees";
  EXPECT_EQ(s.ray_masks[size_t(RayType::Shadow)], 1u);
  auto info = run_rtsim("trace-info --header-only " + out);
  EXPECT_NE(info.out.find("ray masks    shadow 0x01, reflected_shadow 0x01"), std::string::npos)
      << info.out;
  auto sim = run_rtsim("sim " + out + " -o " + json);
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  EXPECT_NE(sim.err.find("a top level per frame, 3 frames"), std::string::npos) << sim.err;
  EXPECT_NE(sim.out.find(" 0 unexplained"), std::string::npos) << sim.out;
  auto flat = run_rtsim("verify " + out + " --flatten");
  EXPECT_EQ(flat.exit_code, 2);
  EXPECT_NE(flat.err.find("cannot keep the workload's instance masks or motion"), std::string::npos)
      << flat.err;
  std::remove(out.c_str());
  std::remove(json.c_str());
}

// pica is built from instances, so a rule can hide its light bulb from shadow rays: the trace
// keeps it as instances (each with its own material), and every ray verifies on two levels.
TEST(CliTrace, PicaInstancesTakeMasks) {
  std::string file = tmp("pica-masks.toml"), out = tmp("pica-masks.rays");
  std::FILE* f = std::fopen(file.c_str(), "w");
  std::fputs(
      "scene = \"pica\"\n[[instances]]\nmatch = \"light\"\nmask = 2\n[ray_masks]\nshadow = 1\n", f);
  std::fclose(f);
  auto r = run_rtsim("trace " + file + " -q --resolution 32x18 -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto info = run_rtsim("trace-info --header-only " + out);
  EXPECT_NE(info.out.find("ray masks    shadow 0x01"), std::string::npos) << info.out;
  auto verify = run_rtsim("verify " + out);
  ASSERT_EQ(verify.exit_code, 0) << verify.err;
  EXPECT_NE(verify.out.find(" 0 mismatches"), std::string::npos) << verify.out;
  std::remove(out.c_str());
}

TEST(CliTrace, InstanceRulesTheSceneCannotTakeAreBadInput) {
  std::string file = tmp("rules.toml"), out = tmp("rules.rays");
  std::remove(out.c_str());
  auto trace_with = [&](const std::string& text) {
    std::FILE* f = std::fopen(file.c_str(), "w");
    std::fputs(text.c_str(), f);
    std::fclose(f);
    return run_rtsim("trace " + file + " -q --resolution 16x9 -o " + out);
  };
  auto r = trace_with("scene = \"cornell\"\n[[instances]]\nmatch = \"*\"\nmask = 1\n");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("builtin:cornell: the scene is one mesh without instances"),
            std::string::npos)
      << r.err;
  r = trace_with("scene = \"city:1000\"\n[[instances]]\nmatch = \"boats\"\nmask = 1\n");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(file + ": line 2: instance rule 'boats' matches no instance's object name"),
            std::string::npos)
      << r.err;
  r = trace_with(
      "scene = \"city:1000\"\nframes = 2\n[[instances]]\nmatch = \"cars\"\n[[instances.key]]\n"
      "[[instances.key]]\ntranslate = [1e16, 0, 0]\n");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("its motion carries it out of range"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  std::remove(file.c_str());
}

TEST(CliTrace, ADegenerateCameraIsBadInputNamingTheSpecAndKey) {
  std::string file = tmp("flat.toml"), out = tmp("flat.rays");
  std::FILE* f = std::fopen(file.c_str(), "w");
  std::fputs("scene = \"cornell\"\n[camera]\nposition = [0, 1, 3]\nlook_at = [0, 1, 3]\n", f);
  std::fclose(f);
  auto r = run_rtsim("trace " + file + " -q --resolution 16x9 -o " + out);
  EXPECT_EQ(r.exit_code, 2) << "it used to trace rays that all miss, exit 0";
  EXPECT_EQ(
      r.err.rfind("rtsim: error: " + file + ": line 4: key 'camera.look_at': equals position", 0),
      0u)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  std::remove(file.c_str());
}

TEST(CliTrace, CameraOptionsPlaceTheViewAndADegenerateOneIsBadInput) {
  std::string out = tmp("placed.rays");
  auto r = run_rtsim(
      "trace grid:64 --resolution 16x9 --camera 0,5,-8 --look-at 0,0,0 --up 0,1,0 -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  StreamHeader h;
  std::vector<Ray> rays = read_all_rays(out, &h);
  ASSERT_FALSE(rays.empty());
  EXPECT_EQ(rays[0].org, glm::vec3(0, 5, -8)) << "camera rays start at --camera";
  EXPECT_NE(r.err.find("trace: no light in the spec or in builtin:grid:64: added a directional "
                       "sun pointing ("),
            std::string::npos)
      << r.err;
  EXPECT_GT(h.counts[size_t(RayType::Shadow)], 0u) << "the added sun gets shadow rays";
  std::remove(out.c_str());

  for (auto [options, message] :
       {std::pair{"--camera 1,2,3 --look-at 1,2,3",
                  "rtsim: error: --camera: the camera position equals the look-at point"},
        {"--camera 0,5,0 --look-at 0,0,0", "rtsim: error: --up: parallel to the view direction"},
        {"--camera 1,2", "rtsim: error: --camera 1,2: expected three numbers X,Y,Z"}}) {
    auto bad =
        run_rtsim(std::string("trace grid:64 -q --resolution 16x9 ") + options + " -o " + out);
    EXPECT_EQ(bad.exit_code, 2) << options;
    EXPECT_EQ(bad.err.rfind(message, 0), 0u) << bad.err;
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
    EXPECT_FALSE(std::filesystem::exists(out));
  }
}

TEST(CliTrace, SameInputsSameBytes) {
  std::string a = tmp("a.rays"), b = tmp("b.rays");
  ASSERT_EQ(run_rtsim("trace pica -q -o " + a + " --resolution 80x45").exit_code, 0);
  ASSERT_EQ(run_rtsim("trace pica -q -o " + b + " --resolution 80x45").exit_code, 0);
  EXPECT_TRUE(test::slurp(a) == test::slurp(b));
  EXPECT_GT(test::slurp(a).size(), 10000u);
  std::remove(a.c_str());
  std::remove(b.c_str());
}

TEST(CliTrace, PreviewAndDensityImages) {
  std::string png = tmp("pica.png");
  auto r = run_rtsim("trace " + spec("pica") + " -q --preview " + png + " --resolution 96x54");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* pass : {"camera", "shadow", "reflection", "reflected_shadow", "diffuse_gi",
                           "gi_light", "ao", "refraction", "translucency", "all"}) {
    std::string path = tmp(std::string("pica.density-") + pass + ".png");
    EXPECT_TRUE(std::filesystem::exists(path)) << path;
    std::remove(path.c_str());
  }
  EXPECT_GT(std::filesystem::file_size(png), 1000u);
  std::remove(png.c_str());
}

TEST(CliTrace, BadInputIsOneLineAndExitCode2) {
  std::string bad = tmp("bad.toml");
  {
    std::FILE* f = std::fopen(bad.c_str(), "w");
    std::fputs("scene = \"cornell\"\n[camera]\nfvo = 40\n", f);
    std::fclose(f);
  }
  auto r = run_rtsim("trace " + bad + " -o " + tmp("x.rays"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "rtsim: error: " + bad + ": line 3: unknown key 'camera.fvo'\n");
  EXPECT_FALSE(std::filesystem::exists(tmp("x.rays")));
  r = run_rtsim("trace cornell -o " + tmp("x.rays") + " --resolution 12");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(test::count_lines(r.err), 1);
  r = run_rtsim("trace no-such-scene.obj -o " + tmp("x.rays"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(test::count_lines(r.err), 1);
  std::remove(bad.c_str());
}

TEST(CliTrace, ListKeysShowsEveryKeyWithItsDefault) {
  auto r = run_rtsim("trace --list-keys");
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("gi.budget"), std::string::npos);
  EXPECT_NE(r.out.find("default 250000 (rays)"), std::string::npos) << r.out;
}

TEST(CliBenchTrace, PrintsTimesRatesAndTheEmbreeReference) {
  auto r = run_rtsim("bench-trace cornell --resolution 64x36");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("Mrays/s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("reference: Embree alone"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace rtsim
