// Units read one way: a size is bytes or a number with a binary suffix (traces/byte_size.h)
// wherever one is read (a config file, --set), bad ones are one error naming the key and its
// place, and a config argument that is a preset's name reads configs/NAME.toml.
#include <gtest/gtest.h>

#include <algorithm>

#include "model/config/config_presets.h"
#include "model/config/hw_config.h"
#include "tests/simcfg/config_files.h"
#include "traces/byte_size.h"
#include "traces/error.h"
#include "traces/text_table.h"

namespace rtsim {
namespace {

using test::error_of;
using test::write_toml;

uint64_t size_of(const std::string& text) {
  uint64_t bytes = 0;
  std::string problem = byte_size_problem(text, &bytes);
  EXPECT_EQ(problem, "") << text;
  return bytes;
}

std::string problem_of(const std::string& text) {
  uint64_t bytes = 0;
  return byte_size_problem(text, &bytes);
}

TEST(ByteSize, SuffixesAreBinary) {
  EXPECT_EQ(size_of("4096"), 4096u);
  EXPECT_EQ(size_of("4096B"), 4096u);
  EXPECT_EQ(size_of("256K"), 256u << 10);
  EXPECT_EQ(size_of("64KiB"), 64u << 10);
  EXPECT_EQ(size_of("4M"), 4u << 20);
  EXPECT_EQ(size_of("4MiB"), 4u << 20);
  EXPECT_EQ(size_of("1G"), uint64_t(1) << 30);
  EXPECT_EQ(size_of("2GiB"), uint64_t(2) << 30);
  EXPECT_EQ(size_of("3T"), uint64_t(3) << 40);
  EXPECT_EQ(size_of("0"), 0u) << "zero is the caller's range to refuse";
  EXPECT_EQ(size_of("16777215T"), uint64_t(16777215) << 40) << "the largest in T";
  EXPECT_EQ(size_of("18446744073709551615"), UINT64_MAX);
}

TEST(ByteSize, BadSuffixesAndOverflowSayWhy) {
  EXPECT_EQ(problem_of("4x"),
            "'4x': unknown suffix 'x' (a size is bytes, or a number with K, "
            "M, G or T (KiB, MiB, GiB, TiB): 64K, 4M)");
  EXPECT_NE(problem_of("4MB").find("unknown suffix 'MB'"), std::string::npos);
  EXPECT_NE(problem_of("4 M").find("unknown suffix ' M'"), std::string::npos);
  EXPECT_NE(problem_of("").find("is not a size"), std::string::npos);
  EXPECT_NE(problem_of("-4M").find("'-4M' is not a size"), std::string::npos);
  EXPECT_NE(problem_of("1.5M").find("unknown suffix '.5M'"), std::string::npos);
  EXPECT_EQ(problem_of("16777216T"), "'16777216T' is more than 2^64-1 bytes");
  EXPECT_EQ(problem_of("18446744073709551616"), "'18446744073709551616' is more than 2^64-1 bytes");
  try {
    parse_byte_size("4x", "--l2");
    ADD_FAILURE() << "4x parsed";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--l2: '4x': unknown suffix", 0), 0u) << e.what();
  }
}

TEST(ByteSize, TextIsTheLargestUnitThatDivides) {
  EXPECT_EQ(byte_size_text(256 << 10), "256K");
  EXPECT_EQ(byte_size_text(1 << 20), "1M");
  EXPECT_EQ(byte_size_text(4 << 20), "4M");
  EXPECT_EQ(byte_size_text(uint64_t(16) << 30), "16G");
  EXPECT_EQ(byte_size_text(1536), "1536");
  EXPECT_EQ(byte_size_text(64), "64");
  EXPECT_EQ(byte_size_text(0), "0");
}

TEST(WholeNumber, DigitsGroupFromTenThousandUp) {
  EXPECT_EQ(whole_number(uint64_t(0)), "0");
  EXPECT_EQ(whole_number(uint64_t(9999)), "9999");
  EXPECT_EQ(whole_number(uint64_t(10000)), "10,000");
  EXPECT_EQ(whole_number(uint64_t(1234567)), "1,234,567");
  EXPECT_EQ(whole_number(UINT64_MAX), "18,446,744,073,709,551,615");
  EXPECT_EQ(whole_number(11603.6), "11,604") << "a real is rounded";
  EXPECT_EQ(whole_number(-1234567.0), "-1,234,567");
  EXPECT_EQ(whole_number(-0.2), "0");
  EXPECT_EQ(whole_number(1e30), "1e+30");
}

TEST(ConfigSizes, FilesAndSetTakeSuffixesOrBytes) {
  HwConfig c = load_hw_config(
      write_toml(
          "[rt.l1]\nsize_bytes = \"16K\"\nline_bytes = \"128\"\n[l2]\nsize_bytes = 1048576\n"),
      {"l2.size_bytes=4M", "treelet_queues.buffer_bytes=64KiB"});
  EXPECT_EQ(first_level(c).cache.size_bytes, 16u << 10);
  EXPECT_EQ(first_level(c).cache.line_bytes, 128u);
  EXPECT_EQ(last_level(c).cache.size_bytes, 4u << 20) << "--set beats the file";
  EXPECT_EQ(c.treelet_queues.buffer.bytes, 64u << 10);
  EXPECT_NE(resolved_toml(c).find("size_bytes = 4194304"), std::string::npos)
      << "the resolved config writes bytes";
}

TEST(ConfigSizes, BadSizesNameTheKeyAndPlace) {
  std::string path = write_toml("[l2]\nsize_bytes = \"4x\"\n");
  EXPECT_EQ(error_of(path), path +
                                ": line 2: key 'l2.size_bytes': '4x': unknown suffix 'x' (a "
                                "size is bytes, or a number with K, M, G or T (KiB, MiB, "
                                "GiB, TiB): 64K, 4M)");
  EXPECT_EQ(error_of("", {"rt.l1.size_bytes=99999999999T"}),
            "--set rt.l1.size_bytes=99999999999T: key 'rt.l1.size_bytes': '99999999999T' is more "
            "than 2^64-1 bytes");
  EXPECT_EQ(
      error_of("", {"l2.size_bytes=0K"}),
      "--set l2.size_bytes=0K: key 'l2.size_bytes': '0K' (0 bytes) is out of range [64, 16G]");
  EXPECT_EQ(error_of("", {"l2.size_bytes=32G"}),
            "--set l2.size_bytes=32G: key 'l2.size_bytes': '32G' (34359738368 bytes) is out of "
            "range [64, 16G]");
  EXPECT_EQ(error_of("", {"l2.size_bytes=-5"}),
            "--set l2.size_bytes=-5: key 'l2.size_bytes': -5 is out of range [64, 16G]");
  EXPECT_NE(error_of("", {"l2.size_bytes=true"})
                .find("key 'l2.size_bytes': expected a size (bytes, or a string such as \"64K\" "
                      "or \"4M\"), got a boolean"),
            std::string::npos);
  EXPECT_EQ(error_of("", {"rt.l1.sector_bytes=0"}), "(no error)") << "0: the whole line";
}

TEST(ConfigSizes, ListedLevelsKeepTheirLines) {
  std::string path = write_toml(
      "[[memory.level]]\nname = \"near\"\nscope = \"unit\"\n\n[[memory.level]]\nname = "
      "\"far\"\nscope = \"shared\"\nsize_bytes = \"2Q\"\n");
  EXPECT_NE(error_of(path).find(path + ": line 8: key 'memory.far.size_bytes': '2Q': unknown "
                                       "suffix 'Q'"),
            std::string::npos)
      << error_of(path);
}

TEST(ConfigSet, AnOverrideThatMakesTheClashIsNamed) {
  // desktop writes the shorthand [rt.l1] and [l2]; the override lists levels under [memory].
  EXPECT_EQ(error_of(RTSIM_SOURCE_DIR "/configs/desktop.toml", {"memory.l2.size_bytes=4M"})
                .rfind("--set memory.l2.size_bytes=4M: [rt.l1] is the shorthand", 0),
            0u)
      << error_of(RTSIM_SOURCE_DIR "/configs/desktop.toml", {"memory.l2.size_bytes=4M"});
  std::string both = write_toml("[l2]\nways = 8\n[memory]\nlevels = [\"a\"]\n");
  EXPECT_EQ(error_of(both, {"memory.a.ways=4"}).rfind(both + ": line 1: [l2] is the shorthand", 0),
            0u)
      << "the file clashes by itself: " << error_of(both, {"memory.a.ways=4"});
}

TEST(ConfigSizes, SizeKeysAreListedAsSizesAndRatesAsNumbers) {
  auto type_of = [](const std::string& key) {
    std::vector<HwConfigKey> keys = hw_config_keys();
    auto it = std::find_if(keys.begin(), keys.end(), [&](auto& k) { return k.key == key; });
    return it == keys.end() ? "(no key)" : it->type + " " + it->unit;
  };
  for (const char* key : {"memory.l1.size_bytes", "memory.l2.line_bytes", "memory.l2.sector_bytes",
                          "dram.row_bytes", "dram.burst_bytes", "treelet_queues.buffer_bytes",
                          "bvh.treelet_bytes", "rt.stack.entry_bytes", "rt.prefetch.max_bytes"})
    EXPECT_EQ(type_of(key), "size bytes") << key;
  EXPECT_EQ(type_of("memory.l2.bytes_per_cycle"), "number bytes/cycle") << "a rate";
  EXPECT_EQ(type_of("memory.l2.ways"), "integer lines");
}

TEST(ConfigPresets, ANameReadsThePreset) {
  EXPECT_EQ(hw_config_path("desktop"), configs_dir() + "/desktop.toml");
  EXPECT_EQ(resolved_toml(load_hw_config("desktop", {"l2.size_bytes=4M"})),
            resolved_toml(load_hw_config(RTSIM_SOURCE_DIR "/configs/desktop.toml",
                                         {"l2.size_bytes=4194304"})));
  EXPECT_EQ(hw_config_path("configs/desktop.toml"), "configs/desktop.toml") << "a path stays";
  EXPECT_EQ(hw_config_path("desktop.toml"), "desktop.toml") << "a .toml name is a file";
  EXPECT_EQ(hw_config_path(""), "") << "the built-in defaults";
  std::vector<std::string> presets = hw_config_presets();
  EXPECT_TRUE(std::is_sorted(presets.begin(), presets.end()));
  EXPECT_NE(std::find(presets.begin(), presets.end(), "mobile"), presets.end());
  EXPECT_EQ(std::find(presets.begin(), presets.end(), "dram"), presets.end()) << "no folders";
}

TEST(ConfigPresets, AnUnknownNameListsThePresets) {
  std::string e = error_of("nosuch");
  EXPECT_EQ(e.rfind("nosuch: no such file, nor a preset " + configs_dir() + "/nosuch.toml", 0), 0u)
      << e;
  EXPECT_NE(e.find("(presets: arc-a770, desktop, desktop-cwbvh8,"), std::string::npos) << e;
  EXPECT_NE(error_of("nosuch.toml").find("nosuch.toml: cannot open the hardware config"),
            std::string::npos);
}

}  // namespace
}  // namespace rtsim
