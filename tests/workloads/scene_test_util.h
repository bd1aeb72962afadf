// Helpers shared by the scene tests: an assertion that loading a spec fails with an InputError
// naming it (and the scratch folders of tests/temp_dir.h).
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
