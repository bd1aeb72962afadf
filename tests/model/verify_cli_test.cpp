// rtsim verify and rtsim bench as a user runs them: streams written with RayStreamWriter.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include "model/verify/ray_samples.h"
#include "run_rtsim.h"
#include "traces/hash.h"
#include "traces/stream.h"
#include "workloads/hardcases.h"
#include "workloads/scene.h"

namespace rtsim {
namespace {

std::string temp_path(const std::string& name) {
  return "/tmp/rtsim-model-" + std::to_string(getpid()) + "-" + name;
}

// A stream over a built-in scene: the hard cases' rays plus camera rays.
std::string write_stream(const std::string& name, const std::string& scene_name) {
  Scene scene = load_scene(scene_name);
  StreamHeader header;
  header.scene_source = scene.source;
  header.scene_fingerprint = scene.fingerprint;
  header.workload = "model-test";
  header.generator = "rtsim model tests";
  std::string path = temp_path(name);
  RayStreamWriter writer(path, header);
  for (const auto& c : hardcases::make_hard_cases(40, 5))
    for (const Ray& ray : c.rays) writer.write(ray);
  for (const Ray& ray : sample_camera_rays(scene.mesh, 48, 32)) writer.write(ray);
  writer.finish();
  return path;
}

class VerifyCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { stream_ = write_stream("hard.rays", "hardcases"); }
  static void TearDownTestSuite() { std::remove(stream_.c_str()); }
  static std::string stream_;
};
std::string VerifyCli::stream_;

TEST_F(VerifyCli, PassesForEveryFormatAndWidth) {
  for (std::string format : {"aabb32", "cwbvh8"})
    for (int width : {2, 4, 6, 8}) {
      auto r = test::run_rtsim("verify " + stream_ + " --format " + format + " --width " +
                               std::to_string(width));
      EXPECT_EQ(r.exit_code, 0) << format << width << "\n" << r.out << r.err;
      EXPECT_NE(r.out.find("unexplained                 0"), std::string::npos) << r.out;
      EXPECT_NE(r.out.find("OK: "), std::string::npos) << r.out;
    }
}

// AMD's radv formats (model/bvh/amd_nodes.h) pass on the hard cases; without the 4-wide,
// one-triangle-leaf settings they need, verify names the missing setting in one line, exit 2.
TEST_F(VerifyCli, PassesForAmdFormatsAndNamesWhatTheyNeed) {
  for (std::string format : {"amd_box32", "amd_box16"}) {
    auto r = test::run_rtsim("verify " + stream_ + " --format " + format +
                             " --width 4 --leaf-size 1 --triangles amd_tri");
    EXPECT_EQ(r.exit_code, 0) << format << "\n" << r.out << r.err;
    EXPECT_NE(r.out.find("bvh4 " + format + " amd_tri"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("OK: "), std::string::npos) << r.out;
    r = test::run_rtsim("verify " + stream_ + " --format " + format + " --width 4 --leaf-size 1");
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("triangle_format is raw: " + format), std::string::npos) << r.err;
  }
  auto r = test::run_rtsim("verify " + stream_ + " --format amd_box32");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.err.find("width is 8: amd_box32 nodes hold at most 4 children"), std::string::npos)
      << r.err;
}

TEST_F(VerifyCli, PrintsSummaryCountersAndHexMismatches) {
  auto r = test::run_rtsim("verify " + stream_ + " --layout breadth-first --max-print 3");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  for (const char* part : {"mismatch class", "edge_or_vertex", "grazing", "degenerate",
                           "equal_t_tie", "range_boundary", "trav_nodes", "trav_prim_hits",
                           "camera", "bvh8 aabb32 raw breadth-first"})
    EXPECT_NE(r.out.find(part), std::string::npos) << part << "\n" << r.out;
  // Mismatching rays, if any, are printed as hex floats.
  if (r.out.find("first ") != std::string::npos) {
    EXPECT_NE(r.out.find("0x"), std::string::npos);
  }
}

// verify checks the BVH a hardware config simulates, as rtsim sim builds it.
TEST_F(VerifyCli, ConfigGivesTheBvhThePresetSimulates) {
  std::string mobile = std::string(RTSIM_SOURCE_DIR) + "/configs/mobile.toml";
  auto r = test::run_rtsim("verify " + stream_ + " --config " + mobile);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("bvh4 aabb32 raw treelet"), std::string::npos) << r.out;
  r = test::run_rtsim("verify " + stream_ + " --config " + mobile + " --set bvh.width=2");
  EXPECT_NE(r.out.find("bvh2 aabb32 raw treelet"), std::string::npos) << r.out;
  r = test::run_rtsim("verify " + stream_);
  EXPECT_NE(r.out.find("bvh8 aabb32 raw treelet"), std::string::npos) << r.out;
  r = test::run_rtsim("verify " + stream_ + " --config " + mobile + " --width 8");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_EQ(test::first_line(r.err),
            "rtsim: error: verify: --config takes the BVH from the hardware config; change it "
            "there or with --set bvh.KEY=VALUE, not with the BVH options");
  r = test::run_rtsim("verify " + stream_ + " --set bvh.nope=1");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(test::first_line(r.err).find("--set bvh.nope=1: unknown key"), std::string::npos)
      << r.err;
}

TEST_F(VerifyCli, SceneFingerprintMismatchIsBadInput) {
  auto r = test::run_rtsim("verify " + stream_ + " --scene cornell");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("fingerprint"), std::string::npos) << r.err;
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
}

TEST_F(VerifyCli, BadInputExitsTwo) {
  EXPECT_EQ(test::run_rtsim("verify /nonexistent/x.rays").exit_code, 2);
  EXPECT_EQ(test::run_rtsim("verify " + stream_ + " --width 9").exit_code, 2);
  EXPECT_EQ(test::run_rtsim("verify " + stream_ + " --format bvh99").exit_code, 2);
  auto r = test::run_rtsim("verify " + stream_ + " --format cwbvh8 --leaf-size 4");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("max_leaf_size"), std::string::npos) << r.err;
}

// A built-in scene has no instance structure: two levels make it one instance.
TEST_F(VerifyCli, InstancesOfAFlatSceneAreOneInstance) {
  auto r = test::run_rtsim("verify " + stream_ + " --instances");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("over 1 instances; bottom: 1 meshes"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("trav_instances 0.00"), std::string::npos) << r.out;
  EXPECT_EQ(test::run_rtsim("verify " + stream_ + " --instances --flatten").exit_code, 2);
}

// The two-level BVH over a scene file's instances (Sponza: 34 objects, each a mesh placed
// once), against Embree's instances: every ray agrees or is explained.
TEST(VerifyCliInstances, TwoLevelSponzaAgreesWithEmbreeInstances) {
  std::string sponza = std::string(RTSIM_SHARED_SCENES) + "/sponza-dabrovic/sponza.obj";
  if (!std::filesystem::exists(sponza)) GTEST_SKIP() << "../shared/scenes is absent: " << sponza;
  std::string stream = temp_path("sponza.rays");
  auto traced =
      test::run_rtsim("trace pica --scene " + sponza + " --resolution 96x54 -q -o " + stream);
  ASSERT_EQ(traced.exit_code, 0) << traced.err;
  for (std::string format : {"aabb32", "cwbvh8"}) {
    auto r = test::run_rtsim("verify " + stream + " --instances --format " + format);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("two levels"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("top: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("over 34 instances; bottom: 34 meshes"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("unexplained                 0"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("trav_instances 0.00"), std::string::npos) << r.out;
  }
  std::remove(stream.c_str());
}

// A one-ray stream of cornell whose float at byte `field` of the ray record is `value`, with
// its chunk CRC fixed up, so that only the ray itself is wrong. Returns the record's offset.
uint64_t write_patched_ray_stream(const std::string& path, size_t field, float value) {
  Scene scene = load_scene("cornell");
  StreamHeader header;
  header.scene_source = scene.source;
  header.scene_fingerprint = scene.fingerprint;
  RayStreamWriter writer(path, header);
  writer.write(sample_camera_rays(scene.mesh, 1, 1)[0]);
  writer.finish();
  std::ifstream in(path, std::ios::binary);
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), {});
  in.close();
  uint32_t header_bytes;
  std::memcpy(&header_bytes, bytes.data() + 12, 4);
  uint64_t record = header_bytes + 4;  // the chunk's ray count, then the record
  std::memcpy(bytes.data() + record + field, &value, 4);
  uint32_t crc = crc32(bytes.data() + header_bytes, 4 + kRayRecordBytes);
  std::memcpy(bytes.data() + header_bytes + 4 + kRayRecordBytes, &crc, 4);
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  return record;
}

// The reader must reject a NaN direction with a clear error before anything is traced.
TEST(VerifyCliInput, NanRayInStreamIsRejected) {
  std::string path = temp_path("nan.rays");
  write_patched_ray_stream(path, 12, std::numeric_limits<float>::quiet_NaN());  // dir.x
  auto r = test::run_rtsim("verify " + path);
  std::remove(path.c_str());
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("NaN"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("OK:"), std::string::npos) << "no ray was traced";
}

// An origin beyond Embree's range (it aborted the process): exit 2 naming the ray and its byte
// offset, and nothing traced.
TEST(VerifyCliInput, ARayBeyondEmbreesRangeIsRejected) {
  std::string path = temp_path("far.rays");
  uint64_t record = write_patched_ray_stream(path, 4, 2e18f);  // org.y
  std::string out = temp_path("far-out");
  for (const std::string& command :
       {std::string("verify "), "sim --no-verify -q -o " + out + " "}) {
    auto r = test::run_rtsim(command + path);
    EXPECT_EQ(r.exit_code, 2) << command << r.out << r.err;
    EXPECT_NE(r.err.find("offset " + std::to_string(record) +
                         ": ray 0: an origin component is beyond +-1.844e18"),
              std::string::npos)
        << command << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(out + "/stats.json")) << "nothing simulated";
  std::filesystem::remove_all(out);
  std::remove(path.c_str());
}

TEST(BenchCli, RunsOnABuiltinScene) {
  auto r = test::run_rtsim("bench --scene grid:20000 --rays 20000 --repeat 1");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  for (const char* part : {"model ", "embree ", "ratio ", "Mrays/s"})
    EXPECT_NE(r.out.find(part), std::string::npos) << part << "\n" << r.out;
}

TEST(BenchCli, MissingSceneFileIsAClearMessage) {
  auto r = test::run_rtsim("bench --scene /nonexistent/conference.obj");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("/nonexistent/conference.obj not found"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace rtsim
