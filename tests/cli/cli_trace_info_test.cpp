// rtsim trace-info on good and damaged ray streams.
#include <gtest/gtest.h>

#include "run_rtsim.h"
#include "stream_test_util.h"

namespace rtsim::test {
namespace {

TEST(CliTraceInfo, PrintsHeaderAndCounts) {
  std::string path = temp_path("info.rays");
  write_stream(path, sample_rays(80));
  RunResult r = run_rtsim("trace-info " + path);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("scene        builtin:cornell\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("fingerprint  0123456789abcdef\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("resolution   64x32\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("rays         80 (all chunks checked)\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  diffuse_gi       10\n"), std::string::npos) << r.out;
  std::remove(path.c_str());
}

TEST(CliTraceInfo, CorruptedByteIsExit2WithFileAndOffset) {
  std::string path = temp_path("corrupt.rays");
  write_stream(path, sample_rays(80), 16);
  auto bytes = read_bytes(path);
  bytes[bytes.size() / 2] ^= 0x40;
  write_bytes(path, bytes);
  RunResult r = run_rtsim("trace-info " + path);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(path + ": offset "), std::string::npos) << r.err;
  std::remove(path.c_str());
}

TEST(CliTraceInfo, TruncatedFileIsExit2) {
  std::string path = temp_path("truncated.rays");
  write_stream(path, sample_rays(80), 16);
  auto bytes = read_bytes(path);
  bytes.resize(bytes.size() - 100);
  write_bytes(path, bytes);
  RunResult r = run_rtsim("trace-info " + path);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("truncated"), std::string::npos) << r.err;
  std::remove(path.c_str());
}

}  // namespace
}  // namespace rtsim::test
