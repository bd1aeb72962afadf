// Every corrupted byte, every truncation and every invalid ray of a .rays file is reported
// as an InputError naming the file and a byte offset at or before the damage.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <regex>

#include "stream_test_util.h"
#include "traces/error.h"
#include "traces/hash.h"

namespace rtsim {
namespace {

// The offset the error names, or -1 when the error is not an InputError with an offset.
long error_offset(const std::string& path) {
  try {
    read_all_rays(path);
  } catch (const InputError& e) {
    std::string msg = e.what();
    std::smatch m;
    if (msg.rfind(path, 0) == 0 && std::regex_search(msg, m, std::regex("offset (\\d+)")))
      return std::stol(m[1]);
    ADD_FAILURE() << "error without file and offset: " << msg;
  }
  return -1;
}

class StreamCorruption : public ::testing::Test {
 protected:
  void SetUp() override {
    test::write_stream(good_, test::sample_rays(20), 8);
    bytes_ = test::read_bytes(good_);
  }
  void TearDown() override {
    std::remove(good_.c_str());
    std::remove(bad_.c_str());
  }
  std::string good_ = test::temp_path("good.rays"), bad_ = test::temp_path("bad.rays");
  std::vector<uint8_t> bytes_;
};

TEST_F(StreamCorruption, EveryFlippedByteIsDetected) {
  for (size_t i = 0; i < bytes_.size(); ++i) {
    for (uint8_t mask : {0x01, 0x80, 0xff}) {
      auto damaged = bytes_;
      damaged[i] ^= mask;
      test::write_bytes(bad_, damaged);
      long offset = error_offset(bad_);
      ASSERT_GE(offset, 0) << "byte " << i << " mask " << int(mask) << " went unnoticed";
      EXPECT_LE(size_t(offset), i) << "error offset after the damaged byte " << i;
    }
  }
}

TEST_F(StreamCorruption, EveryTruncationIsDetected) {
  for (size_t len = 0; len < bytes_.size(); ++len) {
    test::write_bytes(bad_, std::vector<uint8_t>(bytes_.begin(), bytes_.begin() + long(len)));
    long offset = error_offset(bad_);
    ASSERT_GE(offset, 0) << "truncation to " << len << " bytes went unnoticed";
    EXPECT_LE(size_t(offset), len);
  }
}

TEST_F(StreamCorruption, TrailingBytesAreDetected) {
  auto longer = bytes_;
  longer.push_back(0);
  test::write_bytes(bad_, longer);
  EXPECT_EQ(error_offset(bad_), long(bytes_.size()));
}

TEST_F(StreamCorruption, MissingFileNamesTheFile) {
  try {
    read_all_rays("/nonexistent/x.rays");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/x.rays"), std::string::npos);
  }
}

// A NaN written into a ray with a valid checksum: caught by the ray check, not the CRC.
TEST_F(StreamCorruption, NanRayWithValidChecksumIsRejected) {
  size_t header_bytes;
  uint32_t hb;
  std::memcpy(&hb, bytes_.data() + 12, 4);
  header_bytes = hb;
  size_t ray3 = header_bytes + 4 + 3 * kRayRecordBytes;
  float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(bytes_.data() + ray3 + 12, &nan, 4);  // dir.x
  size_t chunk_body = 4 + 8 * kRayRecordBytes;
  uint32_t crc = crc32(bytes_.data() + header_bytes, chunk_body);
  std::memcpy(bytes_.data() + header_bytes + chunk_body, &crc, 4);
  test::write_bytes(bad_, bytes_);
  EXPECT_EQ(error_offset(bad_), long(ray3));
  try {
    read_all_rays(bad_);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ray 3: direction is NaN or Inf"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace rtsim
