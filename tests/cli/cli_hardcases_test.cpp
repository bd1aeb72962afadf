// The hard cases as a workload: rtsim hardcases writes the stream, rtsim verify passes it with
// zero unexplained mismatches on the default and the compressed node format.
#include <gtest/gtest.h>

#include "run_rtsim.h"
#include "stream_test_util.h"

namespace rtsim::test {
namespace {

TEST(CliHardcases, StreamVerifiesWithNothingUnexplained) {
  std::string path = temp_path("hardcases.rays");
  RunResult made = run_rtsim("hardcases --rays-per-case 200 -o " + path);
  ASSERT_EQ(made.exit_code, 0) << made.err;
  EXPECT_NE(made.out.find("wrote " + path), std::string::npos) << made.out;

  StreamHeader header;
  auto rays = read_all_rays(path, &header);
  EXPECT_EQ(header.scene_source, "builtin:hardcases");
  EXPECT_GT(rays.size(), 1000u);
  EXPECT_EQ(run_rtsim("hardcases --rays-per-case 200 -o " + path + ".again").exit_code, 0);
  EXPECT_EQ(read_bytes(path), read_bytes(path + ".again")) << "same seed, same bytes";

  for (const char* format : {"", " --format cwbvh8"}) {
    RunResult verified = run_rtsim("verify " + path + format);
    EXPECT_EQ(verified.exit_code, 0) << format << "\n" << verified.out << verified.err;
  }
  std::remove(path.c_str());
  std::remove((path + ".again").c_str());
}

}  // namespace
}  // namespace rtsim::test
