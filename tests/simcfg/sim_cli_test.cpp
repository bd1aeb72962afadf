// rtsim sim as a user runs it: a stream in, stats.json, config.toml and pixel buffers out,
// every ray verified; bad input ends with one line and exit code 2.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "tests/cli/run_rtsim.h"
#include "traces/stream.h"
#include "workloads/scene.h"
#include "model/verify/ray_samples.h"

namespace rtsim {
namespace {

std::string temp(const std::string& name) {
  return ::testing::TempDir() + "rtsim-sim-cli-" + std::to_string(getpid()) + "-" + name;
}

// A small stream on the built-in pica scene with a 16 x 8 pixel grid.
std::string write_stream() {
  std::string path = temp("pica.rays");
  Scene scene = load_scene("pica");
  StreamHeader header;
  header.scene_source = scene.source;
  header.scene_fingerprint = scene.fingerprint;
  header.width = 16;
  header.height = 8;
  RayStreamWriter writer(path, header);
  for (Ray ray : sample_camera_rays(scene.mesh, 16, 8)) writer.write(ray);
  for (Ray ray : sample_diffuse_rays(scene.mesh, 300, 4)) {
    ray.pixel = ray.pixel % 128;
    writer.write(ray);
  }
  writer.finish();
  return path;
}

TEST(SimCli, WritesResultsAndVerifiesEveryRay) {
  std::string stream = write_stream(), out = temp("out");
  test::RunResult r = test::run_rtsim(
      "sim " + stream + " --config " RTSIM_SOURCE_DIR "/configs/mobile.toml --set rt.count=2 -o " +
      out);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("verify     428 rays against Embree: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" mismatches, 0 unexplained"), std::string::npos) << r.out;
  nlohmann::json doc = nlohmann::json::parse(test::slurp(out + "/stats.json"));
  EXPECT_EQ(doc["summary"]["rays"], 428);
  EXPECT_EQ(doc["config"]["rt"]["count"], 2) << "the override is in the resolved config";
  EXPECT_EQ(doc["verify"]["unexplained"], 0);
  EXPECT_TRUE(std::filesystem::exists(out + "/config.toml"));
  EXPECT_EQ(std::filesystem::file_size(out + "/pixel_nodes.f32"), 16u * 8 * 4);
  std::filesystem::remove_all(out);
  std::filesystem::remove(stream);
}

TEST(SimCli, ASlowMemoryIsNotAStall) {
  // One DRAM channel clocked at 1 MHz (a DRAM clock is 900 core cycles): rays wait for data far
  // longer than sim.stall_cycles, but the data's cycle is known, so the run finishes.
  std::string stream = write_stream(), out = temp("slow");
  test::RunResult r =
      test::run_rtsim("sim " + stream +
                      " --config " RTSIM_SOURCE_DIR
                      "/configs/mobile.toml --set dram.clock_mhz=1 --set dram.channels=1 -q -o " +
                      out);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  nlohmann::json doc = nlohmann::json::parse(test::slurp(out + "/stats.json"));
  EXPECT_GT(doc["summary"]["cycles"].get<double>(), 1e6) << "far beyond the stall cycles";
  std::filesystem::remove_all(out);
  std::filesystem::remove(stream);
}

// The busiest resource leads: a starved DRAM bus is named as the limit, on stdout and in
// stats.json; with every limit raised far, nothing is half busy and the run is latency-bound.
TEST(SimCli, NamesWhatLimitsTheDesign) {
  std::string stream = write_stream(), out = temp("limit");
  std::string mobile = " --config " RTSIM_SOURCE_DIR "/configs/mobile.toml";
  test::RunResult r = test::run_rtsim("sim " + stream + mobile +
                                      " --set dram.channels=1 --set dram.clock_mhz=50 -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  nlohmann::json doc = nlohmann::json::parse(test::slurp(out + "/stats.json"));
  EXPECT_EQ(doc["bottleneck"]["resource"], "DRAM data bus");
  EXPECT_DOUBLE_EQ(doc["bottleneck"]["utilisation"].get<double>(),
                   doc["utilisation"]["dram"].get<double>());
  EXPECT_GT(doc["bottleneck"]["utilisation"].get<double>(), 0.5);
  EXPECT_NE(r.out.find("limit      DRAM data bus "), std::string::npos) << r.out;
  r = test::run_rtsim("sim " + stream + mobile +
                      " --set rt.l1.bytes_per_cycle=0 --set l2.bytes_per_cycle=0 --set "
                      "xbar.bytes_per_cycle=4096 --set rt.box.count=16 --set rt.triangle.count=16 "
                      "--set rt.issue_per_cycle=16 --set dram.channels=64 -q -o " +
                      out);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  doc = nlohmann::json::parse(test::slurp(out + "/stats.json"));
  EXPECT_LT(doc["bottleneck"]["utilisation"].get<double>(), 0.5);
  EXPECT_EQ(doc["bottleneck"]["text"].get<std::string>().rfind("latency: no unit", 0), 0u)
      << doc["bottleneck"];
  std::filesystem::remove_all(out);
  std::filesystem::remove(stream);
}

// A one-triangle OBJ scene in dir, and a stream of one ray at it whose header names the scene
// as `scene_source`.
std::string write_obj_stream(const std::string& dir, const std::string& scene_source) {
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/tri.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  Scene scene = load_scene(dir + "/tri.obj");
  StreamHeader header;
  header.scene_source = scene_source;
  header.scene_fingerprint = scene.fingerprint;
  std::string path = dir + "/one.rays";
  RayStreamWriter writer(path, header);
  Ray ray;
  ray.org = {0.2f, 0.2f, 1.0f};
  ray.dir = {0.0f, 0.0f, -1.0f};
  writer.write(ray);
  writer.finish();
  return path;
}

TEST(SimCli, AStreamsRelativeScenePathIsAlsoTriedBesideTheStream) {
  std::string dir = temp("beside");
  std::string stream = write_obj_stream(dir, "tri.obj");  // relative to where it was traced
  test::RunResult r = test::run_rtsim("sim " + stream + " -q -o " + dir + "/out");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::filesystem::remove_all(dir);
}

TEST(SimCli, AMissingStreamSceneSaysToPassScene) {
  std::string dir = temp("missing");
  std::string stream = write_obj_stream(dir, "gone/tri.obj");
  test::RunResult r = test::run_rtsim("sim " + stream + " -q -o " + dir + "/out");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "rtsim: error: " + stream +
                       ": header: its scene gone/tri.obj is not found (from this folder nor "
                       "from the stream's); pass --scene FILE to name it\n");
  r = test::run_rtsim("sim " + stream + " --scene " + dir + "/tri.obj -q -o " + dir + "/out");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::filesystem::remove_all(dir);
}

TEST(SimCli, BadConfigIsOneLineAndExitCode2) {
  std::string stream = write_stream(), config = temp("bad.toml");
  { std::ofstream(config) << "[rt]\nwarps = 2\nwrap_size = 8\n"; }
  test::RunResult r =
      test::run_rtsim("sim " + stream + " --config " + config + " -o " + temp("never"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(config + ": line 3: unknown key 'rt.wrap_size'"), std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(temp("never"))) << "nothing written";
  r = test::run_rtsim("sim " + stream + " --set rt.count=-1 -o " + temp("never"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  std::filesystem::remove(stream);
  std::filesystem::remove(config);
}

TEST(SimCli, RayTypesSimulatesOnlyTheNamedTypesOfTheStream) {
  std::string stream = write_stream(), out = temp("types");
  test::RunResult r = test::run_rtsim("sim " + stream + " --ray-types diffuse_gi -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("verify     300 rays against Embree"), std::string::npos) << r.out;
  nlohmann::json doc = nlohmann::json::parse(test::slurp(out + "/stats.json"));
  EXPECT_EQ(doc["summary"]["rays"], 300);
  EXPECT_FALSE(doc["ray_types"].contains("camera")) << "the camera rays were skipped";
  for (const char* types : {"shadow", "camera,bogus"}) {
    r = test::run_rtsim("sim " + stream + " --ray-types " + types + " -o " + temp("never"));
    EXPECT_EQ(r.exit_code, 2) << types;
    EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  }
  EXPECT_NE(r.err.find("unknown ray type 'bogus'"), std::string::npos) << r.err;
  std::filesystem::remove_all(out);
  std::filesystem::remove(stream);
}

TEST(SimCli, APrefetchTriggerItsModeCannotUseIsExitCode2) {
  std::string stream = write_stream();
  test::RunResult r =
      test::run_rtsim("sim " + stream + " --set rt.prefetch.trigger=batch -o " + temp("never"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("needs treelet queues"), std::string::npos) << r.err;
  std::filesystem::remove(stream);
}

TEST(SimCli, SortedAndReorderedRunsVerifyEveryRayAndReportTheirStats) {
  std::string stream = write_stream(), out = temp("sorted");
  test::RunResult r = test::run_rtsim("sim " + stream +
                                      " --set sort.key=hash --set rt.mode=packet"
                                      " --set rt.packet.reorder_below=0.5 -o " +
                                      out);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("verify     428 rays against Embree: "), std::string::npos) << r.out;
  nlohmann::json doc = nlohmann::json::parse(test::slurp(out + "/stats.json"));
  const nlohmann::json& c = doc["stats"]["counters"];
  EXPECT_EQ(c["sort.rays"], 428);
  EXPECT_EQ(c["dispatch.pool_empty"], 0) << "the pool has room for the sorting buffer";
  EXPECT_GT(c["rt.packet_reorders"].get<uint64_t>(), 0u);
  EXPECT_EQ(doc["verify"]["unexplained"], 0);
  std::filesystem::remove_all(out);
  std::filesystem::remove(stream);
}

TEST(SimCli, SortingOrReorderingWhereTheModeCannotIsExitCode2) {
  std::string stream = write_stream();
  struct Case {
    const char* set;
    const char* says;
  };
  for (Case c : {Case{"--set sort.key=octant_cell --set rt.mode=treelet", "treelet queues group"},
                 Case{"--set sort.key=hash --set sort.buffer_rays=8", "at least a warp"},
                 Case{"--set rt.packet.reorder_below=0.5", "needs packet mode"},
                 Case{"--set rt.mode=packet --set rt.packet.reorder_below=0.5 "
                      "--set rt.packet.min_width=12",
                      "power of two"}}) {
    test::RunResult r = test::run_rtsim("sim " + stream + " " + c.set + " -o " + temp("never"));
    EXPECT_EQ(r.exit_code, 2) << c.set;
    EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
  }
  std::filesystem::remove(stream);
}

TEST(SimCli, ListKeysPrintsEveryKey) {
  test::RunResult r = test::run_rtsim("sim --list-keys");
  ASSERT_EQ(r.exit_code, 0);
  for (const char* key :
       {"memory.l1.size_bytes", "memory.levels", "treelet_queues.policy", "dram.bytes_per_cycle",
        "rt.box.issue_width", "bvh.node_format", "sim.stall_cycles"})
    EXPECT_NE(r.out.find(key), std::string::npos) << key;
}

}  // namespace
}  // namespace rtsim
