// The memory side of whole simulations on every preset: with the DRAM lightly loaded, its mean
// latency is the unloaded latency the config implies (requests are served in time order, so
// none waits behind a request dated later).
#include <gtest/gtest.h>

#include <filesystem>

#include "model/config/hw_config.h"
#include "tests/sc/sim_test_util.h"

namespace rtsim {
namespace {

double counter(const nlohmann::json& doc, const std::string& name) {
  const nlohmann::json& stats = doc["stats"];
  return stats["counters"].contains(name) ? stats["counters"][name].get<double>()
                                          : stats["derived"][name].get<double>();
}

TEST(SimMemory, LightlyLoadedDramHasItsUnloadedLatencyOnEveryPreset) {
  test::SimScene s;
  std::vector<Ray> rays = test::mixed_rays(s.scene, 1500, 7);
  int presets = 0;
  for (const auto& entry : std::filesystem::directory_iterator(RTSIM_SOURCE_DIR "/configs")) {
    if (entry.path().extension() != ".toml") continue;
    ++presets;
    HwConfig config = load_hw_config(entry.path().string(), {});
    nlohmann::json doc = test::simulate(config, s.scene, rays);
    std::string name = entry.path().filename().string();
    double utilisation = counter(doc, "dram.utilisation");
    ASSERT_LT(utilisation, 0.10) << name << ": the stream must load the DRAM lightly";
    double unloaded = config.dram.latency + config.l2.line_bytes / config.dram.bytes_per_cycle;
    double mean = counter(doc, "dram.mean_latency");
    EXPECT_NEAR(mean / unloaded, 1.0, 0.10)
        << name << ": mean DRAM latency " << mean << " at " << utilisation * 100
        << "% utilisation, unloaded " << unloaded;
  }
  EXPECT_GE(presets, 5);
}

}  // namespace
}  // namespace rtsim
