// A device set: the devices that render one frame together, how they are linked, and which
// split strategies to compare (model/multi/README.md lists every key). TOML, in configs/multi/:
//   name, description; [link] [flow] [split] [report] sections of single keys;
//   [[device]] config (a hardware config, relative to this file), count, set (overrides);
//   [[change]] frame, device, config, set: from that frame on, the device's hardware changes
//   (relative to the device's own; an empty change restores it).
// Device 0 is the primary of the mGPU flow. Every key is read in one place, device_set.cpp.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/config/config_reader.h"
#include "model/config/hw_config.h"
#include "model/multi/frame_split.h"
#include "model/multi/mgpu_flow.h"
#include "model/multi/split_policy.h"

namespace rtsim::multi {

// A device's hardware: a config file (empty: the built-in defaults) and key=value overrides.
struct DeviceHardware {
  std::string config;
  std::vector<std::string> sets;
};

// From `frame` on (until the device's next change), the device's hardware is its own with this
// change applied: config, if not empty, replaces its file; sets are added to its own sets.
// Changes do not accumulate: an empty change restores the device's own hardware.
struct DeviceChange {
  uint32_t frame = 0, device = 0;
  DeviceHardware hardware;
};

struct DeviceSet {
  std::string file;  // where it was read from ("" if built from the command line)
  std::string name = "devices", description;
  FlowConfig flow;
  std::vector<SplitStrategy> strategies{SplitStrategy::Static, SplitStrategy::Balanced,
                                        SplitStrategy::Cost, SplitStrategy::Current};
  ScanOrder order = ScanOrder::Rows;
  SampleUnit samples = SampleUnit::Rays;  // what the balanced split counts
  double settle_pct = 5.0;  // a balancer has settled once the max deviation stays below this
  std::vector<DeviceHardware> devices;
  std::vector<DeviceChange> changes;  // by frame
};

// Reads a device set file (path empty: the defaults, with no devices) and applies "key=value"
// overrides of its single keys. Throws InputError naming the file (or --device-set) and line for a
// syntax error, a wrong type, a value out of range, an unknown key, or a change that names a
// device that does not exist. Device hardware configs are not read here (DeviceConfigs does).
DeviceSet load_device_set(const std::string& path, const std::vector<std::string>& overrides = {});

// Every key, with its type, default, unit and description.
std::vector<ConfigKeyDoc> device_set_keys();

// The set as nested JSON (written next to every result).
nlohmann::ordered_json device_set_json(const DeviceSet& set);

// The hardware of every device in every frame, each distinct config loaded once.
class DeviceConfigs {
 public:
  // hw_overrides apply to every device (after its own sets). Throws InputError for a config
  // that does not load.
  DeviceConfigs(const DeviceSet& set, const std::vector<std::string>& hw_overrides = {});
  uint32_t devices() const { return uint32_t(base_.size()); }
  // Index into configs() of the device's hardware in that frame.
  uint32_t index(uint32_t device, uint32_t frame);
  const std::vector<HwConfig>& configs() const { return configs_; }
  // The hardware description that index() resolved, for reports.
  const std::vector<std::string>& labels() const { return labels_; }

 private:
  std::vector<DeviceHardware> base_;
  std::vector<DeviceChange> changes_;
  std::vector<std::string> hw_overrides_;
  std::map<std::string, uint32_t> known_;
  std::vector<HwConfig> configs_;
  std::vector<std::string> labels_;
};

}  // namespace rtsim::multi
