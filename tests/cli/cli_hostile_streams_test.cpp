// Hostile ray streams and sizes (issue 63): headers whose grid, frames or counts the stream
// cannot back, rays outside the header's grid or frames, a ray whose far hits overflow t, and
// the memory plan under `ulimit -v`, for configs and for the rays a command generates. Each ends
// with one line naming the file or option and the place, exit 2, and nothing written.
#include <gtest/gtest.h>

#include <filesystem>

#include "run_rtsim.h"
#include "stream_test_util.h"
#include "tests/temp_dir.h"
#include "traces/hash.h"
#include "traces/stream_codec.h"

namespace rtsim::test {
namespace {

// The bytes of a stream with this header and rays, as written, whatever the header says (the
// writer refuses what these tests feed the reader).
std::string stream_bytes(const StreamHeader& header, const std::vector<Ray>& rays) {
  std::vector<uint8_t> bytes = encode_header(header);
  auto chunk = [&bytes](const std::vector<Ray>& chunk_rays) {
    std::vector<uint8_t> body;
    ByteWriter w(body);
    w.put(uint32_t(chunk_rays.size()));
    for (const Ray& ray : chunk_rays) encode_ray(ray, body);
    w.put(crc32(body.data(), body.size()));
    bytes.insert(bytes.end(), body.begin(), body.end());
  };
  if (!rays.empty()) chunk(rays);
  chunk({});
  return std::string(bytes.begin(), bytes.end());
}

// The header of a 4 x 2 trace of the built-in Cornell box (so the commands find its scene),
// counting these rays.
StreamHeader header_for(const std::vector<Ray>& rays) {
  static const StreamHeader cornell = [] {
    std::string traced = scratch_path("cornell.rays");
    EXPECT_EQ(run_rtsim("trace cornell -q --resolution 4x2 -o " + traced).exit_code, 0);
    StreamHeader h;
    read_all_rays(traced, &h);
    return h;
  }();
  StreamHeader h = cornell;
  h.counts = {};
  for (const Ray& ray : rays) h.counts[size_t(ray.type)]++;
  return h;
}

// Runs each reading command on the stream and checks the one-line refusal (verify has no
// --quiet: its error is the line after the BVH build's, which a bad ray's comes after).
void expect_refused(const std::string& stream, const std::string& place, const std::string& what) {
  TempDir out;
  for (std::string command :
       {std::string("trace-info "), "sim -q -o " + out.path("sim") + " ", std::string("verify ")}) {
    RunResult r = run_rtsim(command + stream);
    std::string error = r.err.substr(r.err.rfind('\n', r.err.size() - 2) + 1);
    EXPECT_EQ(r.exit_code, 2) << command << "\n" << r.err;
    EXPECT_EQ(count_lines(command == "verify " ? error : r.err), 1) << r.err;
    EXPECT_EQ(error.rfind("rtsim: error: " + stream + ": " + place + ": ", 0), 0u) << r.err;
    EXPECT_NE(error.find(what), std::string::npos) << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(out.path("sim/stats.json")));
  EXPECT_FALSE(std::filesystem::exists(out.path("sim/pixel_cycles.f32")));
}

Ray one_ray(uint32_t pixel = 0, uint32_t frame = 0) {
  Ray ray;
  ray.org = {278, 274, 279};
  ray.dir = {0, 0, 1};
  ray.pixel = pixel;
  ray.frame = frame;
  return ray;
}

TEST(CliHostileStreams, AGridTheRaysCannotBackIsRefusedBeforeAnyBuffer) {
  TempDir dir;
  StreamHeader h = header_for({one_ray()});
  h.width = h.height = 16384;  // 200 bytes claiming 268M pixels: 3 GB of pixel buffers
  std::string stream = dir.write("bomb.rays", stream_bytes(h, {one_ray()}));
  expect_refused(stream, "offset 36",
                 "pixel grid 16384 x 16384 has 268435456 pixels, more than 16777216 beyond the "
                 "stream's 1 rays");
}

TEST(CliHostileStreams, AGridSideOrFramesBeyondTheMaximumAreRefused) {
  TempDir dir;
  StreamHeader h = header_for({one_ray()});
  h.width = h.height = 0xffffffffu;
  expect_refused(dir.write("side.rays", stream_bytes(h, {one_ray()})), "offset 36",
                 "pixel grid 4294967295 x 4294967295: a side is beyond 65536");
  h = header_for({one_ray()});
  h.width = 0;
  expect_refused(dir.write("half.rays", stream_bytes(h, {one_ray()})), "offset 36",
                 "pixel grid 0 x 2: one side is 0");
  h = header_for({one_ray()});
  h.frame_count = 0xffffffffu;
  expect_refused(dir.write("frames.rays", stream_bytes(h, {one_ray()})), "offset 32",
                 "4294967295 frames: more than 100000");
}

TEST(CliHostileStreams, CountsBeyondWhatTheFileHoldsAreRefused) {
  TempDir dir;
  StreamHeader h = header_for({one_ray()});
  h.counts[1] = uint64_t(1) << 40;
  expect_refused(dir.write("counts.rays", stream_bytes(h, {one_ray()})), "offset 56",
                 "header counts 1099511627776 shadow rays, more than the file's");
}

TEST(CliHostileStreams, ARayOutsideTheGridOrFramesIsRefusedNamingIt) {
  TempDir dir;
  std::vector<Ray> rays = {one_ray(), one_ray(8)};
  std::string pixel = dir.write("pixel.rays", stream_bytes(header_for(rays), rays));
  std::string offset = "offset " + std::to_string(encode_header(header_for(rays)).size() + 4 + 44);
  expect_refused(pixel, offset, "ray 1: pixel 8 is beyond the header's 4 x 2 grid");
  rays = {one_ray(0, 1)};
  std::string frame = dir.write("frame.rays", stream_bytes(header_for(rays), rays));
  expect_refused(frame, "offset " + std::to_string(encode_header(header_for(rays)).size() + 4),
                 "ray 0: frame 1 is beyond the header's 1 frames");
}

TEST(CliHostileStreams, ARayWhoseFarHitsOverflowTMissesAsInEmbree) {
  // Direction (0, 0, 1e-45): the back wall, 280 away, is at t = 2e47, beyond every float.
  TempDir dir;
  Ray ray = one_ray();
  ray.dir = {0, 0, 1e-45f};
  std::string stream = dir.write("tiny.rays", stream_bytes(header_for({ray}), {ray}));
  RunResult verified = run_rtsim("verify " + stream);
  EXPECT_EQ(verified.exit_code, 0) << verified.out << verified.err;
  RunResult simulated = run_rtsim("sim -q " + stream + " -o " + dir.path("sim"));
  EXPECT_EQ(simulated.exit_code, 0) << simulated.out << simulated.err;
}

TEST(CliHostileStreams, AddressSpaceLimitIsPlannedFor) {
  TempDir dir;
  RunResult r =
      run_program("sh -c 'ulimit -v 6000000; exec " RTSIM_EXE,
                  "trace cornell --resolution 10000x10000 -o " + dir.path("x.rays") + "'");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("cornell: tracing 10000 x 10000 pixels"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("GB available; lower the resolution"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir.path(""))) << "no stream, no temporary";
}

// Runs rtsim with RTSIM_MAX_MEMORY at 1 GB.
RunResult run_in_1gb(const std::string& args) {
  setenv("RTSIM_MAX_MEMORY", "1000000000", 1);
  RunResult r = run_rtsim(args);
  unsetenv("RTSIM_MAX_MEMORY");
  return r;
}

TEST(CliHostileStreams, AConfigIsPlannedNamingTheKeyThatTakesMost) {
  RunResult r = run_in_1gb("scene-info grid:10 --bvh --set rt.count=1024 --set rt.warps=1024");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err,
            "rtsim: error: --set rt.count=1024 --set rt.warps=1024: simulating this machine needs "
            "about 34.5 GB of memory, "
            "more than the 1.0 GB available; lower rt.count * rt.warps * rt.warp_size\n");
  r = run_in_1gb("scene-info grid:10 --bvh --set l2.size_bytes=17179869184");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("; lower l2.size_bytes\n"), std::string::npos) << r.err;
  EXPECT_EQ(run_in_1gb("scene-info grid:10 --bvh").exit_code, 0) << "the defaults fit";
}

TEST(CliHostileStreams, GeneratedRayCountsAreRangeCheckedAndPlanned) {
  for (std::string args : {"bench --scene grid:10 --rays 1e10", "bench --scene grid:10 --rays 0",
                           "bench-sim --scene grid:10 --rays 18446744073709551615"}) {
    RunResult r = run_rtsim(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("--rays"), std::string::npos) << r.err;
  }
  RunResult r = run_in_1gb("bench-sim --scene grid:10 --rays 100000000");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err,
            "rtsim: error: --rays: 100000000 generated rays needs about 6.4 GB of memory, more "
            "than the 1.0 GB available; ask for fewer rays\n");
  TempDir dir;
  r = run_rtsim("hardcases --rays-per-case 16777216 -o " + dir.path("hc.rays"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("rtsim: error: --rays-per-case 16777216: ", 0), 0u) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir.path("")));
}

TEST(CliHostileStreams, AFullDiskSaysWhy) {
  RunResult r = run_rtsim("trace cornell -q --resolution 4x2 -o /dev/full");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "rtsim: error: /dev/full: cannot write: No space left on device\n");
  // A result file linked to /dev/full is written in place, as on a full disk.
  TempDir dir;
  std::vector<Ray> rays = {one_ray()};
  std::string stream = dir.write("one.rays", stream_bytes(header_for(rays), rays));
  std::filesystem::create_directory(dir.path("sim"));
  std::filesystem::create_symlink("/dev/full", dir.path("sim/pixel_cycles.f32"));
  r = run_rtsim("sim -q " + stream + " -o " + dir.path("sim"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "rtsim: error: " + dir.path("sim/pixel_cycles.f32") +
                       ": cannot write: No space left on device\n");
}

}  // namespace
}  // namespace rtsim::test
