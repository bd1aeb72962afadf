// The cache levels of a hardware config: [[memory.level]] in order, overrides by level name,
// the [rt.l1]/[xbar]/[l2] shorthand (and refusing both), and errors that name the place.
#include <gtest/gtest.h>

#include <fstream>

#include "model/config/hw_config.h"
#include "tests/simcfg/config_files.h"
#include "tests/temp_dir.h"
#include "traces/error.h"

namespace rtsim {
namespace {

using test::error_of;
using test::write_toml;

const char* kThreeLevels = R"(
[[memory.level]]
name = "l0"
size_bytes = 16384
hit_latency = 9

[[memory.level]]
name = "l2"
scope = "group:2"
size_bytes = 262144
link_latency = 4

[[memory.level]]
name = "ic"
scope = "shared"
fill = "victim"
size_bytes = 4194304
slices = 4
)";

TEST(MemoryConfig, LevelsAreReadInOrderWithTheirKeys) {
  HwConfig c = load_hw_config(write_toml(kThreeLevels));
  ASSERT_EQ(c.memory.size(), 3u);
  EXPECT_EQ(c.memory[0].name, "l0");
  EXPECT_EQ(c.memory[0].cache.hit_latency, 9u);
  EXPECT_EQ(c.memory[1].scope, LevelScope::Group);
  EXPECT_EQ(c.memory[1].group, 2u);
  EXPECT_EQ(c.memory[2].fill, LevelFill::Victim);
  EXPECT_EQ(c.memory[2].slices, 4u);
  EXPECT_EQ(level_instances(c.memory[1], c.rt_units), 2u) << "4 units, 2 to a group";
}

TEST(MemoryConfig, ALevelsKeyIsSetByItsNameAndTheResolvedConfigReadsBack) {
  std::string path = write_toml(kThreeLevels);
  HwConfig c = load_hw_config(path, {"memory.ic.size_bytes=8388608", "memory.l2.link_latency=7"});
  EXPECT_EQ(c.memory[2].cache.size_bytes, 8388608u);
  EXPECT_EQ(c.memory[1].link.latency, 7u);
  std::string resolved = resolved_toml(c);
  EXPECT_EQ(resolved_toml(load_hw_config(write_toml(resolved))), resolved);
  std::string e = error_of(path, {"memory.l3.size_bytes=1024"});
  EXPECT_NE(e.find("--set memory.l3.size_bytes=1024: memory.l3: no level of that name (levels: "
                   "l0, l2, ic)"),
            std::string::npos)
      << e;
}

TEST(MemoryConfig, TheShorthandIsTheTwoLevelList) {
  HwConfig c =
      load_hw_config(write_toml("[rt.l1]\nsize_bytes = 8192\n[xbar]\nlatency = 3\n"
                                "[l2]\nslices = 2\n"));
  ASSERT_EQ(c.memory.size(), 2u);
  EXPECT_EQ(c.memory[0].name, "l1");
  EXPECT_EQ(c.memory[0].cache.size_bytes, 8192u);
  EXPECT_EQ(c.memory[0].link.latency, 3u) << "[xbar] is l1's link";
  EXPECT_EQ(c.memory[1].scope, LevelScope::Shared);
  EXPECT_EQ(c.memory[1].slices, 2u);
  EXPECT_EQ(load_hw_config("", {"l2.size_bytes=4194304"}).memory[1].cache.size_bytes, 4194304u);
}

TEST(MemoryConfig, TheShorthandBesideALevelListIsOneErrorNamingIt) {
  std::string path = write_toml(std::string(kThreeLevels) + "\n[l2]\nsize_bytes = 65536\n");
  std::string e = error_of(path);
  EXPECT_NE(e.find(path + ": line 20: [l2] is the shorthand"), std::string::npos) << e;
  e = error_of(write_toml(kThreeLevels), {"l2.size_bytes=65536"});
  EXPECT_NE(e.find("--set l2.size_bytes=65536: [l2] is the shorthand"), std::string::npos) << e;
}

TEST(MemoryConfig, BadLevelsAreOneLineNamingTheLevel) {
  std::string e = error_of(write_toml("[[memory.level]]\nsize_bytes = 4096\n"));
  EXPECT_NE(e.find("line 1: a [[memory.level]] needs name"), std::string::npos) << e;
  e = error_of(write_toml("[[memory.level]]\nname = \"a\"\n[[memory.level]]\nname = \"a\"\n"));
  EXPECT_NE(e.find("line 3: two [[memory.level]] tables are named 'a'"), std::string::npos) << e;
  e = error_of(write_toml("[[memory.level]]\nname = \"a\"\nsize_byte = 4096\n"));
  EXPECT_NE(e.find("line 3: unknown key 'memory.a.size_byte'"), std::string::npos) << e;
  e = error_of(write_toml("[[memory.level]]\nname = \"a\"\nscope = \"group:0\"\n"));
  EXPECT_NE(e.find("'group:0' is not unit, group:N"), std::string::npos) << e;
  e = error_of(write_toml("[[memory.level]]\nname = \"a\"\nscope = \"shared\"\n"));
  EXPECT_NE(e.find("[memory.a] the first level is the RT unit's own"), std::string::npos) << e;
  e = error_of(write_toml("[rt.l1]\nsize_bytes = 1000\n"));
  EXPECT_NE(e.find("[rt.l1] size_bytes must be a positive multiple"), std::string::npos)
      << "the shorthand's section as written: " << e;
}

TEST(MemoryConfig, TheFourLevelExampleLoads) {
  HwConfig c = load_hw_config(RTSIM_SOURCE_DIR "/configs/examples/four-levels.toml");
  ASSERT_EQ(c.memory.size(), 4u);
  EXPECT_EQ(level_instances(c.memory[1], c.rt_units), 2u) << "8 units, 4 to a group";
  EXPECT_EQ(c.memory[3].fill, LevelFill::Victim);
}

}  // namespace
}  // namespace rtsim
