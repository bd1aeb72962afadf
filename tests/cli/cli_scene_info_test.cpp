// rtsim scene-info on built-in scenes, real scene files and bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "run_rtsim.h"

namespace rtsim::test {
namespace {

TEST(CliSceneInfo, BuiltinGridHasExactlyTheRequestedTriangles) {
  RunResult r = run_rtsim("scene-info grid:12345");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("triangles    12345\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("scene        builtin:grid:12345\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("fingerprint  "), std::string::npos);
}

TEST(CliSceneInfo, SameSceneSameFingerprint) {
  EXPECT_EQ(run_rtsim("scene-info cornell").out, run_rtsim("scene-info builtin:cornell").out);
  EXPECT_NE(run_rtsim("scene-info foliage:100").out, run_rtsim("scene-info foliage:101").out);
}

TEST(CliSceneInfo, SharedCornellBoxLoads) {
  std::string path = std::string(RTSIM_SHARED_SCENES) + "/cornell-box/CornellBox-Original.obj";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "../shared/scenes is absent: " << path;
  RunResult r = run_rtsim("scene-info " + path);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("triangles    36\n"), std::string::npos) << r.out;
}

TEST(CliSceneInfo, MissingFileIsOneLineAndExit2) {
  RunResult r = run_rtsim("scene-info /nonexistent/scene.obj");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("/nonexistent/scene.obj"), std::string::npos) << r.err;
}

TEST(CliSceneInfo, ZeroTrianglesIsOneLineAndExit2) {
  std::string path = "/tmp/rtsim-cli-empty-" + std::to_string(getpid()) + ".obj";
  std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  RunResult r = run_rtsim("scene-info " + path);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
  std::remove(path.c_str());
}

TEST(CliSceneInfo, NanVertexIsOneLineAndExit2) {
  std::string path = "/tmp/rtsim-cli-nan-" + std::to_string(getpid()) + ".obj";
  std::ofstream(path) << "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n";
  RunResult r = run_rtsim("scene-info " + path);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
  std::remove(path.c_str());
}

TEST(CliSceneInfo, UnsupportedFormatIsOneLineAndExit2) {
  std::string path = "/tmp/rtsim-cli-" + std::to_string(getpid()) + ".xyz";
  std::ofstream(path) << "hello\n";
  RunResult r = run_rtsim("scene-info " + path);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
  std::remove(path.c_str());
}

}  // namespace
}  // namespace rtsim::test
