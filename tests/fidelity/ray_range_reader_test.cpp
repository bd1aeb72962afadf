// The range reader returns exactly the rays the stream reader returns at those positions, across
// chunk boundaries, and rejects a truncated file.
#include <gtest/gtest.h>

#include <filesystem>

#include "model/fidelity/ray_range_reader.h"
#include "tests/fidelity/fidelity_test_util.h"
#include "traces/error.h"

namespace rtsim {
namespace {

TEST(RayRangeReader, ReadsTheSameRaysAsTheStreamReader) {
  std::string path = test::small_stream("grid:600", 5500);
  std::vector<Ray> all = read_all_rays(path);
  RayRangeReader reader(path);
  ASSERT_EQ(reader.rays(), all.size());
  for (auto [begin, end] : {std::pair<uint64_t, uint64_t>{0, 10},
                            {995, 1005},
                            {2999, 4001},
                            {5490, 5500},
                            {5400, 9999}}) {
    std::vector<Ray> got;
    reader.read(begin, end, got);
    ASSERT_EQ(got.size(), std::min<uint64_t>(end, all.size()) - begin) << begin << ".." << end;
    for (size_t i = 0; i < got.size(); ++i)
      EXPECT_TRUE(got[i] == all[begin + i]) << "ray " << begin + i;
  }
  std::filesystem::remove(path);
}

TEST(RayRangeReader, RejectsATruncatedStream) {
  std::string path = test::small_stream("grid:600", 3000);
  std::filesystem::resize_file(path, std::filesystem::file_size(path) - 500);
  EXPECT_THROW(RayRangeReader{path}, InputError);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace rtsim
