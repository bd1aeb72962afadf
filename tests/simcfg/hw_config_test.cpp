// The hardware config: presets load, every key has a default, unit and description and is
// documented in model/SIM-REFERENCE.md, bad input is one clear error naming the file, line and
// key, and --set overrides any key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "model/config/hw_config.h"
#include "tests/simcfg/config_files.h"
#include "tests/temp_dir.h"
#include "traces/error.h"

namespace rtsim {
namespace {

using test::error_of;
using test::write_toml;

TEST(HwConfig, EveryPresetLoadsAndRoundTrips) {
  int presets = 0;
  for (const auto& entry : std::filesystem::directory_iterator(RTSIM_SOURCE_DIR "/configs")) {
    if (entry.path().extension() != ".toml") continue;
    ++presets;
    HwConfig config = load_hw_config(entry.path().string());
    std::string resolved = resolved_toml(config);
    HwConfig again = load_hw_config(write_toml(resolved));
    EXPECT_EQ(resolved_toml(again), resolved) << entry.path();
    EXPECT_EQ(config.name, entry.path().stem().string()) << "name matches the file";
  }
  EXPECT_GE(presets, 4) << "mobile, desktop, cwbvh8 and treelet variants";
}

TEST(HwConfig, PresetsDifferWhereTheyShould) {
  HwConfig mobile = load_hw_config(RTSIM_SOURCE_DIR "/configs/mobile.toml");
  HwConfig desktop = load_hw_config(RTSIM_SOURCE_DIR "/configs/desktop.toml");
  HwConfig cw = load_hw_config(RTSIM_SOURCE_DIR "/configs/desktop-cwbvh8.toml");
  HwConfig tq = load_hw_config(RTSIM_SOURCE_DIR "/configs/desktop-treelet.toml");
  EXPECT_LT(mobile.rt_units, desktop.rt_units);
  EXPECT_LT(last_level(mobile).cache.size_bytes, last_level(desktop).cache.size_bytes);
  EXPECT_EQ(cw.bvh.node_format, NodeFormat::Cwbvh8);
  EXPECT_EQ(tq.rt.mode, TraversalMode::Treelet);
  EXPECT_EQ(resolved_json(tq)["memory"], resolved_json(desktop)["memory"]) << "same caches";
}

// configs/arc-a770.toml is xe-hpg.toml under its old name: the config format has no include,
// so the file is a copy, and every key but the name and description must stay equal.
TEST(HwConfig, ArcA770IsAnAliasOfXeHpg) {
  HwConfig alias = load_hw_config(RTSIM_SOURCE_DIR "/configs/arc-a770.toml");
  HwConfig xe = load_hw_config(RTSIM_SOURCE_DIR "/configs/xe-hpg.toml");
  EXPECT_EQ(alias.name, "arc-a770");
  alias.name = xe.name;
  alias.description = xe.description;
  EXPECT_EQ(resolved_toml(alias), resolved_toml(xe)) << "edit xe-hpg.toml, then copy it here";
}

// The vendor presets' test units do the tests a clock their vendors publish (configs/SOURCES.md;
// `rtsim validate --quick` measures them as ceiling.box_tests and ceiling.triangle_tests).
// NVIDIA publishes ratios only: Ampere twice Turing's triangle rate, Ada twice Ampere's.
TEST(HwConfig, VendorPresetsTestAtTheirPublishedRates) {
  struct Rate {
    const char* preset;
    uint32_t box, triangle;
    bool shared;
  };
  for (const Rate& r :
       {Rate{"rdna2", 4, 1, true}, Rate{"rdna3", 4, 1, true}, Rate{"rdna4", 8, 2, true},
        Rate{"xe-hpg", 12, 1, false}, Rate{"xe2", 18, 2, false}}) {
    HwConfig c = load_hw_config(std::string(RTSIM_SOURCE_DIR "/configs/") + r.preset + ".toml");
    EXPECT_EQ(c.rt.box.count * c.rt.box.issue_width, r.box) << r.preset;
    EXPECT_EQ(c.rt.triangle.count * c.rt.triangle.issue_width, r.triangle) << r.preset;
    EXPECT_EQ(c.rt.test_issue == TestIssue::Shared, r.shared) << r.preset;
  }
  auto triangles = [](const char* preset) {
    HwConfig c = load_hw_config(std::string(RTSIM_SOURCE_DIR "/configs/") + preset + ".toml");
    EXPECT_EQ(c.bvh.node_format, NodeFormat::Cwbvh8) << preset << ": the stand-in format";
    return c.rt.triangle.count * c.rt.triangle.issue_width;
  };
  EXPECT_EQ(triangles("rtx3080"), 2 * triangles("rtx2080ti"));
  EXPECT_EQ(triangles("rtx4090"), 2 * triangles("rtx3080"));
}

TEST(HwConfig, EveryKeyIsDocumented) {
  std::ifstream in(RTSIM_SOURCE_DIR "/model/SIM-REFERENCE.md");
  std::stringstream doc;
  doc << in.rdbuf();
  std::vector<HwConfigKey> keys = hw_config_keys();
  EXPECT_GT(keys.size(), 40u);
  for (const HwConfigKey& k : keys) {
    EXPECT_FALSE(k.description.empty()) << k.key;
    EXPECT_NE(doc.str().find("`" + k.key + "`"), std::string::npos)
        << k.key << " in SIM-REFERENCE.md";
  }
}

TEST(HwConfig, UnknownKeyNamesKeyAndLine) {
  std::string path = write_toml("[rt]\ncount = 2\n\n[rt.l1]\nsize_bytes = 8192\nsize_byte = 1\n");
  std::string e = error_of(path);
  EXPECT_NE(e.find(path + ": line 6"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown key 'rt.l1.size_byte'"), std::string::npos) << e;
  EXPECT_NE(e.find("size_bytes"), std::string::npos) << "lists the keys of [rt.l1]: " << e;
  EXPECT_NE(error_of(write_toml("[gpu]\nx = 1\n")).find("unknown key 'gpu'"), std::string::npos);
}

TEST(HwConfig, WrongTypeRangeAndSyntaxAreClearErrors) {
  std::string e = error_of(write_toml("[dram]\nlatency = \"fast\"\n"));
  EXPECT_NE(e.find("line 2"), std::string::npos) << e;
  EXPECT_NE(e.find("'dram.latency': expected an integer"), std::string::npos) << e;
  e = error_of(write_toml("[rt]\nwarp_size = 0\n"));
  EXPECT_NE(e.find("out of range"), std::string::npos) << e;
  e = error_of(write_toml("[rt]\nmode = \"sideways\"\n"));
  EXPECT_NE(e.find("'sideways' is not one of depth_first, treelet, packet"), std::string::npos);
  e = error_of(write_toml("[rt\ncount = 1\n"));
  EXPECT_NE(e.find("line 1"), std::string::npos) << e;
  e = error_of(write_toml("[rt.l1]\nsize_bytes = 1000\n"));
  EXPECT_NE(e.find("[rt.l1] size_bytes must be a positive multiple"), std::string::npos) << e;
  EXPECT_NE(error_of("/nonexistent/hw.toml").find("cannot open"), std::string::npos);
}

TEST(HwConfig, SetOverridesAnyKey) {
  HwConfig c = load_hw_config(RTSIM_SOURCE_DIR "/configs/mobile.toml",
                              {"rt.l1.size_bytes=8192", "rt.mode=treelet", "clock.ghz=2",
                               "dram.bytes_per_cycle=12.5", "sim.quantum_cycles=4"});
  EXPECT_EQ(first_level(c).cache.size_bytes, 8192u);
  EXPECT_EQ(c.rt.mode, TraversalMode::Treelet);
  EXPECT_DOUBLE_EQ(c.clock_ghz, 2.0);
  EXPECT_DOUBLE_EQ(c.dram.bytes_per_cycle, 12.5);
  EXPECT_EQ(c.sim.quantum_cycles, 4u);
  std::string e = error_of("", {"rt.l1.sise=1"});
  EXPECT_NE(e.find("--set rt.l1.sise"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown key"), std::string::npos) << e;
  EXPECT_NE(error_of("", {"rt.count"}).find("expected KEY=VALUE"), std::string::npos);
  EXPECT_NE(error_of("", {"rt.count=many"}).find("--set rt.count"), std::string::npos);
}

TEST(HwConfig, ImpossibleCombinationIsAnError) {
  std::string e = error_of("", {"rt.mode=treelet", "treelet_queues.max_rays=16"});
  EXPECT_NE(e.find("max_rays (16) must be at least the ray slots"), std::string::npos) << e;
  e = error_of("", {"rt.mode=treelet", "treelet_queues.buffer_bytes=100"});
  EXPECT_NE(e.find("buffer_bytes (100) holds no ray state: one takes 120 bytes"), std::string::npos)
      << e;
  e = error_of("", {"rt.mode=treelet", "shader.model=simt"});
  EXPECT_NE(e.find("[shader] model = \"simt\" needs whole warps"), std::string::npos) << e;
  e = error_of("", {"rt.refill=slot", "shader.model=simt"});
  EXPECT_NE(e.find("needs whole warps"), std::string::npos) << e;
  EXPECT_EQ(error_of("", {"rt.mode=packet", "shader.model=simt"}), "(no error)");
}

TEST(HwConfig, ShaderCyclesPerRayType) {
  HwConfig c = load_hw_config("", {"shader.model=simt", "shader.shadow.miss=7"});
  EXPECT_EQ(c.shader.model, ShaderModel::Simt);
  EXPECT_EQ(c.shader.cycles[int(RayType::Shadow)].miss, 7u);
  EXPECT_EQ(c.shader.cycles[int(RayType::Camera)].hit,
            ShaderConfig::default_shader_cycles()[int(RayType::Camera)].hit);
  EXPECT_EQ(load_hw_config("").shader.model, ShaderModel::None) << "off unless asked for";
  std::string e = error_of("", {"shader.sky.miss=1"});
  EXPECT_NE(e.find("unknown key 'shader.sky"), std::string::npos) << e;
}

}  // namespace
}  // namespace rtsim

namespace rtsim {
namespace {

TEST(DramPresets, EveryPresetLoadsWithinItsStandardsRelations) {
  for (std::string name : {"gddr6-14", "gddr6-16", "lpddr5-6400", "hbm3-6400", "ddr5-4800"}) {
    BankedDramConfig c = dram_preset_config(name);
    EXPECT_EQ(banked_dram_config_problem(c), "") << name;
    EXPECT_EQ(c.preset, name);
  }
  BankedDramConfig hbm = dram_preset_config("hbm3-6400");
  EXPECT_EQ(hbm.channels, 32u);
  EXPECT_EQ(hbm.timing.tCL, 26u);
  EXPECT_NEAR(hbm.peak_gb_per_s(), 819.2, 0.1) << "a stack's bandwidth (JESD238)";
  EXPECT_NEAR(dram_preset_config("gddr6-16").peak_gb_per_s() / 8, 32.0, 1e-9) << "per x16 channel";
  EXPECT_NEAR(dram_preset_config("gddr6-14").peak_gb_per_s() / 8, 28.0, 1e-9);
  EXPECT_NEAR(dram_preset_config("lpddr5-6400").peak_gb_per_s() / 4, 12.8, 1e-9);
  EXPECT_NEAR(dram_preset_config("ddr5-4800").peak_gb_per_s() / 2, 19.2, 1e-9);
}

TEST(DramPresets, APresetFillsTheKeysAndKeysBesideItOverride) {
  HwConfig c =
      load_hw_config(write_toml("[dram]\nmodel = \"banked\"\npreset = \"lpddr5-6400\"\n"
                                "channels = 8\n[dram.timing]\ntCL = 20\n"));
  EXPECT_EQ(c.dram_model, DramModel::Banked);
  EXPECT_EQ(c.banked_dram.preset, "lpddr5-6400");
  EXPECT_EQ(c.banked_dram.channels, 8u);
  EXPECT_EQ(c.banked_dram.timing.tCL, 20u);
  EXPECT_EQ(c.banked_dram.timing.tRCD_RD, 15u) << "the preset's";
  std::string resolved = resolved_toml(c);
  EXPECT_EQ(resolved_toml(load_hw_config(write_toml(resolved))), resolved) << "round trip";
}

TEST(DramPresets, BadDramConfigsNameTheFileAndKey) {
  std::string unknown = write_toml("[dram]\nmodel = \"banked\"\npreset = \"gddr7\"\n");
  std::string e = error_of(unknown);
  EXPECT_NE(e.find(unknown), std::string::npos) << e;
  EXPECT_NE(e.find("dram.preset"), std::string::npos) << e;
  EXPECT_NE(e.find("gddr6-16"), std::string::npos) << "lists the known presets: " << e;

  e = error_of("", {"dram.model=banked", "dram.timing.tRC=40"});
  EXPECT_NE(e.find("[dram] timing.tRC (40) must be at least tRAS + tRP (91)"), std::string::npos)
      << e;
  e = error_of("", {"dram.model=banked", "dram.timing.tRRD_L=2"});
  EXPECT_NE(e.find("timing.tRRD_L (2) must be at least tRRD_S"), std::string::npos) << e;
  e = error_of("", {"dram.model=banked", "dram.mapping=row:bank:column"});
  EXPECT_NE(e.find("does not cover the address: it leaves out rank, bankgroup, channel"),
            std::string::npos)
      << e;
  e = error_of("", {"dram.model=banked", "dram.mapping=row:rank:bankgroup:bank:column:chan"});
  EXPECT_NE(e.find("leaves out channel"), std::string::npos) << e;
  e = error_of("", {"dram.model=banked", "dram.write_low=30"});
  EXPECT_NE(e.find("write_low (30) < write_high (24)"), std::string::npos) << e;
  EXPECT_EQ(error_of("", {"dram.model=simple", "dram.timing.tRC=40"}), "(no error)")
      << "the simple model does not use the banked keys";
}

}  // namespace
}  // namespace rtsim
