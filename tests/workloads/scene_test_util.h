// Helpers shared by the scene tests: base64 for data URIs, an assertion that loading a spec fails
// with an InputError naming it (and the scratch folders of tests/temp_dir.h).
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/temp_dir.h"
#include "traces/error.h"
#include "workloads/scene.h"

namespace rtsim::test {

// Base64 (RFC 4648), for data URIs.
inline std::string base64(const std::string& in) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < in.size(); i += 3) {
    size_t left = in.size() - i;
    uint32_t n = uint32_t(uint8_t(in[i])) << 16;
    if (left > 1) n |= uint32_t(uint8_t(in[i + 1])) << 8;
    if (left > 2) n |= uint32_t(uint8_t(in[i + 2]));
    out += table[(n >> 18) & 63];
    out += table[(n >> 12) & 63];
    out += left > 1 ? table[(n >> 6) & 63] : '=';
    out += left > 2 ? table[n & 63] : '=';
  }
  return out;
}

// Loads spec expecting an InputError whose message starts with "spec: " (or "named: " when
// given) and contains fragment; returns the message.
inline std::string expect_input_error(const std::string& spec, const std::string& fragment,
                                      const std::string& named = "") {
  try {
    Scene scene = load_scene(spec);
    ADD_FAILURE() << "loading '" << spec << "' should fail, got " << scene.triangle_count()
                  << " triangles";
  } catch (const InputError& e) {
    std::string message = e.what();
    std::string prefix = (named.empty() ? spec : named) + ": ";
    EXPECT_EQ(message.rfind(prefix, 0), 0u) << "message should name the file: " << message;
    EXPECT_NE(message.find(fragment), std::string::npos)
        << "message should say '" << fragment << "': " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "message should be one line: " << message;
    return message;
  }
  return "";
}

}  // namespace rtsim::test
