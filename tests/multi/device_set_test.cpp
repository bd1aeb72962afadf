// Device sets (configs/multi/*.toml): every preset loads, keys are checked like hardware
// configs (unknown keys and bad values name the file and line), changes resolve per frame.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "model/multi/device_set.h"
#include "tests/temp_dir.h"
#include "traces/error.h"

namespace rtsim::multi {
namespace {

const std::string kConfigs = std::string(RTSIM_SOURCE_DIR) + "/configs";

std::string write_set(const std::string& text) {
  std::string path = test::scratch_path("set.toml");
  std::ofstream(path) << text;
  return path;
}

std::string error_of(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    load_device_set(write_set(text), sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(DeviceSet, EveryPresetLoadsWithItsHardware) {
  int presets = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kConfigs + "/multi")) {
    DeviceSet set = load_device_set(entry.path().string());
    DeviceConfigs configs(set);
    EXPECT_GE(configs.devices(), 1u) << entry.path();
    ++presets;
  }
  EXPECT_GE(presets, 3);
}

TEST(DeviceSet, FourMobileIsFourEqualDevices) {
  DeviceSet set = load_device_set(kConfigs + "/multi/four-mobile.toml");
  EXPECT_EQ(set.name, "four-mobile");
  ASSERT_EQ(set.devices.size(), 4u);
  EXPECT_EQ(std::filesystem::path(set.devices[3].config).filename(), "mobile.toml");
  EXPECT_TRUE(std::filesystem::exists(set.devices[3].config)) << "relative to the set's file";
  EXPECT_EQ(set.strategies.size(), 4u);
  DeviceConfigs configs(set);
  for (uint32_t d = 0; d < 4; ++d) EXPECT_EQ(configs.index(d, 0), 0u) << "one config, shared";
  EXPECT_EQ(configs.configs()[0].rt_units, 4u);
}

TEST(DeviceSet, HeterogeneousSetChangesHardwareAtItsFrames) {
  DeviceSet set = load_device_set(kConfigs + "/multi/hetero-mobile.toml");
  DeviceConfigs configs(set);
  ASSERT_EQ(configs.devices(), 4u);
  EXPECT_EQ(configs.configs()[configs.index(3, 0)].rt_units, 2u) << "half the units";
  EXPECT_EQ(configs.configs()[configs.index(0, 9)].clock_ghz, 0.9);
  EXPECT_EQ(configs.configs()[configs.index(0, 10)].clock_ghz, 0.45) << "throttled at 10";
  EXPECT_EQ(configs.configs()[configs.index(0, 25)].clock_ghz, 0.9) << "back at 20";
  EXPECT_EQ(configs.configs()[configs.index(1, 15)].clock_ghz, 0.9) << "others unchanged";
}

TEST(DeviceSet, OverridesAndDefaults) {
  DeviceSet set = load_device_set(write_set("[[device]]\ncount = 2\n"),
                                  {"link.bandwidth_gbps=32", "split.order=columns"});
  EXPECT_EQ(set.flow.link.bandwidth_gbps, 32);
  EXPECT_EQ(set.order, ScanOrder::Columns);
  EXPECT_EQ(load_device_set(write_set("[split]\norder = \"interleaved\"\n")).order,
            ScanOrder::Interleaved);
  EXPECT_EQ(set.devices.size(), 2u);
  EXPECT_EQ(set.devices[0].config, "") << "built-in hardware defaults";
  EXPECT_EQ(set.flow.raygen_ns_per_pixel, FlowConfig{}.raygen_ns_per_pixel);
}

TEST(DeviceSet, BadInputNamesFileLineAndKey) {
  {
    std::string e = error_of("name = \"x\"\n[link]\nbandwith_gbps = 3\n");
    EXPECT_NE(e.find("line 3"), std::string::npos) << e;
    EXPECT_NE(e.find("link.bandwith_gbps"), std::string::npos) << e;
  }
  std::string e = error_of("[[device]]\ncount = 2\n\n[[device]]\nconfg = \"a.toml\"\n");
  EXPECT_NE(e.find("line 5"), std::string::npos) << e;
  EXPECT_NE(e.find("confg"), std::string::npos) << e;
  e = error_of("[split]\nstrategies = [\"static\", \"afr\"]\n");
  EXPECT_NE(e.find("afr"), std::string::npos) << e;
  e = error_of("[split]\nstrategies = \"static\"\n");
  EXPECT_NE(e.find("array of strings"), std::string::npos) << e;
  e = error_of("[link]\nlatency_us = -1.0\n");
  EXPECT_NE(e.find("out of range"), std::string::npos) << e;
  e = error_of("[[device]]\n[[change]]\nframe = 3\ndevice = 4\n");
  EXPECT_NE(e.find("device 4 does not exist"), std::string::npos) << e;
  e = error_of("", {"link.nope=1"});
  EXPECT_NE(e.find("--device-set link.nope"), std::string::npos) << e;
  e = error_of("[link\n");
  EXPECT_NE(e.find("line 1"), std::string::npos) << e;
}

TEST(DeviceSet, HardwareThatDoesNotLoadIsAnInputError) {
  DeviceSet set = load_device_set(write_set("[[device]]\nset = [\"rt.count=0\"]\n"));
  EXPECT_THROW(DeviceConfigs configs(set), InputError);
  DeviceSet none = load_device_set("");
  EXPECT_THROW(DeviceConfigs configs(none), InputError) << "no devices";
}

TEST(DeviceSet, KeysAreDocumented) {
  std::vector<std::string> keys;
  for (const ConfigKeyDoc& d : device_set_keys()) {
    keys.push_back(d.key);
    EXPECT_FALSE(d.description.empty()) << d.key;
  }
  for (const char* k :
       {"link.bandwidth_gbps", "link.latency_us", "link.shared", "flow.raygen_ns_per_pixel",
        "flow.output_bytes_per_pixel", "split.strategies", "split.order", "report.settle_pct",
        "device[].config", "device[].count", "device[].set", "change[].frame", "change[].device"})
    EXPECT_NE(std::find(keys.begin(), keys.end(), k), keys.end()) << k;
}

}  // namespace
}  // namespace rtsim::multi
