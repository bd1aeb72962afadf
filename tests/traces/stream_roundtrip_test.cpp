// Writing then reading a stream gives back every ray bit for bit, and the header as written.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include <sys/resource.h>

#include "stream_test_util.h"
#include "traces/error.h"

namespace rtsim {
namespace {

using test::sample_rays;
using test::temp_path;

TEST(StreamRoundTrip, EveryRayTypeBitForBit) {
  std::string path = temp_path("roundtrip.rays");
  auto rays = sample_rays(1000);  // 1000 rays, chunks of 64: 15 full chunks and a partial one
  test::write_stream(path, rays);
  StreamHeader header;
  auto back = read_all_rays(path, &header);
  ASSERT_EQ(back.size(), rays.size());
  for (size_t i = 0; i < rays.size(); ++i) EXPECT_TRUE(back[i] == rays[i]) << "ray " << i;
  for (int t = 0; t < kRayTypeCount; ++t)
    EXPECT_EQ(header.counts[t], 125u) << ray_type_name(RayType(t));
  EXPECT_EQ(header.scene_source, "builtin:cornell");
  EXPECT_EQ(header.scene_fingerprint, 0x0123456789abcdefull);
  EXPECT_EQ(header.workload, "test");
  EXPECT_EQ(header.seed, 42u);
  EXPECT_EQ(header.frame_count, 3u);
  EXPECT_EQ(header.width, 64u);
  EXPECT_EQ(header.height, 32u);
  std::remove(path.c_str());
}

TEST(StreamRoundTrip, FileSizeIsExactlyHeaderChunksAndEndMarker) {
  std::string path = temp_path("size.rays");
  test::write_stream(path, sample_rays(100), 64);  // chunks of 64 and 36 rays
  // Fixed fields, three strings, empty instance settings (8 ray masks, three counts), CRC.
  auto header_bytes = 112 + 3 * 4 + std::string("builtin:cornell").size() + 4 + 10 + 20 + 4;
  auto expected = header_bytes + (8 + 64 * kRayRecordBytes) + (8 + 36 * kRayRecordBytes) + 8;
  EXPECT_EQ(std::filesystem::file_size(path), expected);
  std::remove(path.c_str());
}

TEST(StreamRoundTrip, EmptyStreamIsValid) {
  std::string path = temp_path("empty.rays");
  test::write_stream(path, {});
  StreamHeader header;
  EXPECT_TRUE(read_all_rays(path, &header).empty());
  EXPECT_EQ(header.total_rays(), 0u);
  std::remove(path.c_str());
}

TEST(StreamRoundTrip, SameRaysGiveIdenticalBytes) {
  std::string a = temp_path("a.rays"), b = temp_path("b.rays");
  test::write_stream(a, sample_rays(300));
  test::write_stream(b, sample_rays(300));
  EXPECT_EQ(test::read_bytes(a), test::read_bytes(b));
  std::remove(a.c_str());
  std::remove(b.c_str());
}

TEST(StreamWriter, UnfinishedWriterLeavesNoFile) {
  std::string path = temp_path("unfinished.rays");
  {
    RayStreamWriter writer(path, test::sample_header());
    for (const Ray& r : sample_rays(10)) writer.write(r);
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  for (const auto& entry : std::filesystem::directory_iterator("/tmp"))
    EXPECT_EQ(entry.path().string().find(path + ".tmp"), std::string::npos) << entry.path();
}

TEST(StreamWriter, FinalNameAppearsOnlyAtFinish) {
  std::string path = temp_path("atomic.rays");
  RayStreamWriter writer(path, test::sample_header());
  for (const Ray& r : sample_rays(200)) writer.write(r);
  EXPECT_FALSE(std::filesystem::exists(path));
  writer.finish();
  EXPECT_TRUE(std::filesystem::exists(path));
  std::remove(path.c_str());
}

TEST(StreamWriter, RejectsNanRay) {
  RayStreamWriter writer(temp_path("nan.rays"), test::sample_header());
  Ray ray;
  ray.org.y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(writer.write(ray), std::invalid_argument);
}

TEST(StreamWriter, RefusesWhatAReaderWould) {
  StreamHeader header = test::sample_header();  // 64 x 32 pixels, 3 frames
  header.width = kMaxGridSide + 1;
  EXPECT_THROW(RayStreamWriter(temp_path("side.rays"), header), std::invalid_argument);
  RayStreamWriter writer(temp_path("outside.rays"), test::sample_header());
  Ray ray;
  ray.pixel = 64 * 32;
  EXPECT_THROW(writer.write(ray), std::invalid_argument) << "pixel beyond the grid";
  ray.pixel = 0;
  ray.frame = 3;
  EXPECT_THROW(writer.write(ray), std::invalid_argument) << "frame beyond the frames";
  header = test::sample_header();
  header.width = header.height = 4097;  // 16,785,409 pixels: 8,193 beyond 2^24 for no rays
  RayStreamWriter sparse(temp_path("sparse.rays"), header);
  EXPECT_THROW(sparse.finish(), InputError);
  EXPECT_FALSE(std::filesystem::exists(temp_path("sparse.rays")));
}

long peak_rss_kb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

TEST(StreamReader, ReadsAndWritesInConstantMemory) {
  // 2M rays are 88 MB on disk; writer and reader each hold one chunk, so the peak barely moves.
  std::string path = temp_path("long.rays");
  long before = peak_rss_kb();
  {
    StreamHeader header = test::sample_header(16384);
    header.width = 2048;  // 2,097,152 pixels: one for each ray
    header.height = 1024;
    RayStreamWriter writer(path, header);
    Ray ray;
    for (uint32_t i = 0; i < 2000000; ++i) {
      ray.pixel = i;
      writer.write(ray);
    }
    writer.finish();
  }
  RayStreamReader reader(path);
  std::vector<Ray> batch;
  uint64_t total = 0, pixel_sum = 0;
  while (reader.next_batch(batch, 1000) > 0) {
    total += batch.size();
    for (const Ray& r : batch) pixel_sum += r.pixel;
  }
  EXPECT_EQ(total, 2000000u);
  EXPECT_EQ(pixel_sum, 1999999ull * 2000000ull / 2);
  EXPECT_LT(peak_rss_kb() - before, 16 * 1024) << "peak memory grew with the stream length";
  std::remove(path.c_str());
}

}  // namespace
}  // namespace rtsim
