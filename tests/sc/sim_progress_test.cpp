// Progress of a simulation: outside a terminal, one line at each tenth of the stream and
// nothing else, 100% last; with an unknown total, nothing.
#include "model/sc/sim_progress.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "model/sched/ray_context.h"

namespace rtsim {
namespace {

std::string run(uint64_t total, uint64_t retire) {
  std::FILE* out = std::tmpfile();
  SimProgress progress(total, out);
  RayContext ray;
  for (uint64_t i = 0; i < retire; ++i) progress.retired(ray, Cycle(10 * i));
  progress.finish();
  std::string text(size_t(std::ftell(out)), '\0');
  std::rewind(out);
  text.resize(std::fread(text.data(), 1, text.size(), out));
  std::fclose(out);
  return text;
}

TEST(SimProgress, ALineAtEachTenthOutsideATerminal) {
  std::string text = run(1000, 1000);
  size_t lines = 0;
  for (char c : text) lines += c == '\n';
  EXPECT_EQ(lines, 10u) << text;
  EXPECT_NE(text.find("sim:  10%  100 of 1000 rays, cycle 990\n"), std::string::npos) << text;
  EXPECT_NE(text.find("sim: 100%  1000 of 1000 rays"), std::string::npos) << text;
}

TEST(SimProgress, NothingWithoutATotalOrForAFewRays) {
  EXPECT_EQ(run(0, 500), "");
  std::string small = run(5, 5);
  const std::string last = "sim: 100%  5 of 5 rays, cycle 40\n";
  EXPECT_EQ(small.rfind(last), small.size() - last.size()) << small;
  EXPECT_EQ(small.find("sim: 100%"), small.rfind("sim: 100%")) << "100% once";
}

}  // namespace
}  // namespace rtsim
