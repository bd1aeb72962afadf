// refuse_overwriting (issue 63): an output that is an input, or another output, however its path
// is spelt, is refused; outputs that replace nothing (devices) are not compared.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/temp_dir.h"
#include "traces/error.h"
#include "traces/output_file.h"

namespace rtsim {
namespace {

namespace fs = std::filesystem;

// The InputError's message, or "" when refuse_overwriting accepts.
std::string refusal(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
  try {
    refuse_overwriting(inputs, outputs);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(RefuseOverwriting, SameFileByAnySpellingIsRefused) {
  test::TempDir dir;
  std::string scene = dir.write("scene.obj", "v 0 0 0\n");
  fs::create_symlink(scene, dir.path("soft.rays"));
  fs::create_hard_link(scene, dir.path("hard.rays"));
  fs::create_directory(dir.path("sub"));
  for (std::string spelling : {scene, dir.path("soft.rays"), dir.path("hard.rays"),
                               dir.path("sub/../scene.obj"), dir.path("./scene.obj")})
    EXPECT_EQ(refusal({{"the scene", scene}}, {{"-o", spelling}}),
              spelling + ": -o: is the same file as the scene (" + scene +
                  "); writing it would replace that; choose another -o");
  std::string cwd = fs::current_path().string();
  fs::current_path(dir.path("sub"));
  EXPECT_NE(refusal({{"the scene", scene}}, {{"-o", "../scene.obj"}}), "") << "a relative path";
  fs::current_path(cwd);
  EXPECT_EQ(refusal({{"the scene", scene}}, {{"-o", dir.path("other.rays")}}), "");
}

TEST(RefuseOverwriting, TwoOutputsThatAreOneNewFileAreRefused) {
  test::TempDir dir;
  EXPECT_EQ(refusal({}, {{"-o", dir.path("x.png")}, {"--preview", dir.path("y.png")}}), "");
  EXPECT_NE(refusal({}, {{"-o", dir.path("x.png")}, {"--preview", dir.path("./x.png")}}), "");
  fs::create_symlink(dir.path("new.png"), dir.path("link.png"));
  EXPECT_NE(refusal({}, {{"-o", dir.path("new.png")}, {"--preview", dir.path("link.png")}}), "")
      << "a link to a file not yet written";
}

TEST(RefuseOverwriting, DevicesAndEmptyPathsAreNotCompared) {
  EXPECT_EQ(refusal({}, {{"-o", "/dev/null"}, {"--preview", "/dev/null"}}), "");
  EXPECT_EQ(refusal({{"--config", ""}}, {{"-o", ""}}), "");
  EXPECT_TRUE(writes_regular_file("/nonexistent-folder/x.png"));
  EXPECT_FALSE(writes_regular_file("/dev/null"));
}

}  // namespace
}  // namespace rtsim
