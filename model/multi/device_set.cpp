#include "model/multi/device_set.h"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "traces/error.h"

namespace rtsim::multi {
namespace {

std::string line_of(const toml::node* node) {
  if (!node || !node->source().begin) return "";
  return fmt::format("line {}", node->source().begin.line);
}

// Every key of an element of an array of tables must be one that was read for it.
void check_element_keys(const toml::table& element, const std::string& prefix,
                        const ConfigReadContext& ctx) {
  for (auto&& [name, node] : element) {
    std::string full = prefix + "." + std::string(name.str());
    if (std::find(ctx.known.begin(), ctx.known.end(), full) != ctx.known.end()) continue;
    std::string known;
    for (const std::string& k : ctx.known)
      if (k.rfind(prefix + ".", 0) == 0) known += (known.empty() ? "" : ", ") + k;
    throw_input_error(ctx.file, line_of(&node),
                      fmt::format("unknown key '{}' (keys: {})", full, known));
  }
}

// A config path beside file; a preset's name that is no file there stays a name
// (model/config/config_presets.h).
std::string relative_to(const std::string& file, const std::string& path) {
  if (path.empty() || file.empty() || std::filesystem::path(path).is_absolute()) return path;
  std::filesystem::path beside = std::filesystem::path(file).parent_path() / path;
  if (path.find('/') == std::string::npos && beside.extension() != ".toml" &&
      !std::filesystem::exists(beside))
    return path;
  return beside.lexically_normal().string();
}

DeviceHardware read_hardware(ConfigReader& r, const std::string& file, const char* config_desc,
                             const char* sets_desc) {
  DeviceHardware h;
  h.config = relative_to(file, r.text("config", "", config_desc));
  h.sets = r.strings("set", {}, sets_desc);
  return h;
}

void read_devices(const toml::table& root, DeviceSet& s, ConfigReadContext& ctx) {
  const char* prefix = "device[]";
  const toml::node* node = root.get("device");
  const toml::array* array = node ? node->as_array() : nullptr;
  if (node && (!array || !array->is_array_of_tables()))
    throw_input_error(ctx.file, line_of(node), "'device' must be an array of tables: [[device]]");
  size_t elements = array ? array->size() : 0;
  for (size_t i = 0; i < std::max<size_t>(elements, 1); ++i) {  // one empty read documents keys
    const toml::table* table = i < elements ? array->get(i)->as_table() : nullptr;
    ConfigReader r(table, prefix, ctx);
    DeviceHardware h = read_hardware(
        r, ctx.file,
        "hardware config of these devices, relative to this file, or a preset's name (empty: "
        "built-in defaults)",
        "hardware key=value overrides, as rtsim sim --set takes them");
    auto count =
        uint32_t(r.integer("count", 1, "devices", "identical devices of this hardware", 1, 1024));
    if (!table) break;
    check_element_keys(*table, prefix, ctx);
    for (uint32_t k = 0; k < count; ++k) s.devices.push_back(h);
  }
}

void read_changes(const toml::table& root, DeviceSet& s, ConfigReadContext& ctx) {
  const char* prefix = "change[]";
  const toml::node* node = root.get("change");
  const toml::array* array = node ? node->as_array() : nullptr;
  if (node && (!array || !array->is_array_of_tables()))
    throw_input_error(ctx.file, line_of(node), "'change' must be an array of tables: [[change]]");
  size_t elements = array ? array->size() : 0;
  for (size_t i = 0; i < std::max<size_t>(elements, 1); ++i) {
    const toml::table* table = i < elements ? array->get(i)->as_table() : nullptr;
    ConfigReader r(table, prefix, ctx);
    DeviceChange c;
    c.frame =
        uint32_t(r.integer("frame", 1, "frame", "first frame with the new hardware", 0, 1u << 30));
    c.device =
        uint32_t(r.integer("device", 0, "index", "which device changes (0: primary)", 0, 1023));
    c.hardware = read_hardware(
        r, ctx.file, "the device's hardware config from this frame on (empty: the device's own)",
        "overrides added to the device's own from this frame on (empty: none)");
    if (!table) break;
    check_element_keys(*table, prefix, ctx);
    if (c.device >= s.devices.size() && !s.devices.empty())
      r.fail("device",
             fmt::format("device {} does not exist ({} devices)", c.device, s.devices.size()));
    s.changes.push_back(c);
  }
  std::stable_sort(s.changes.begin(), s.changes.end(),
                   [](const DeviceChange& a, const DeviceChange& b) { return a.frame < b.frame; });
}

// Every single key of a device set, read once, here. Defaults are the values already in `s`.
void read_single_keys(ConfigReader& r, DeviceSet& s) {
  s.name = r.text("name", s.name, "the set's name, carried into results");
  s.description = r.text("description", s.description, "what the set models");

  ConfigReader link = r.section("link");
  LinkConfig& l = s.flow.link;
  l.bandwidth_gbps = link.real("bandwidth_gbps", l.bandwidth_gbps, "GB/s",
                               "effective bandwidth of one copy", 1e-6, 1e6);
  l.latency_us = link.real("latency_us", l.latency_us, "us",
                           "fixed cost of each copy (submission and synchronisation)", 0, 1e6);
  l.shared = link.boolean("shared", l.shared,
                          "one copy queue through system memory for all copies, both ways "
                          "(false: each device has a link of its own)");

  ConfigReader flow = r.section("flow");
  FlowConfig& f = s.flow;
  f.raygen_ns_per_pixel =
      flow.real("raygen_ns_per_pixel", f.raygen_ns_per_pixel, "ns",
                "G-buffer and ray generation on the primary, per pixel", 0, 1e6);
  f.filter_ns_per_pixel = flow.real("filter_ns_per_pixel", f.filter_ns_per_pixel, "ns",
                                    "filtering of the results on the primary, per pixel", 0, 1e6);
  f.input_bytes_per_pixel =
      flow.real("input_bytes_per_pixel", f.input_bytes_per_pixel, "bytes",
                "G-buffer data copied to a device per pixel of its region", 0, 1e6);
  f.bytes_per_sample = flow.real("bytes_per_sample", f.bytes_per_sample, "bytes",
                                 "copied per camera sample of a region (its position)", 0, 1e6);
  f.bytes_per_ray = flow.real("bytes_per_ray", f.bytes_per_ray, "bytes",
                              "copied per ray of a region, if rays are shipped", 0, 1e6);
  f.output_bytes_per_pixel = flow.real("output_bytes_per_pixel", f.output_bytes_per_pixel, "bytes",
                                       "tracing results copied back per pixel", 0, 1e6);

  ConfigReader split = r.section("split");
  std::vector<std::string> names;
  for (SplitStrategy st : s.strategies) names.push_back(strategy_name(st));
  names = split.strings("strategies", names,
                        "strategies compared side by side: static, balanced, cost, current");
  s.strategies.clear();
  for (const std::string& n : names) {
    auto st = strategy_from_name(n);
    if (!st)
      split.fail("strategies",
                 fmt::format("'{}' is not one of static, balanced, cost, current", n));
    if (std::find(s.strategies.begin(), s.strategies.end(), *st) == s.strategies.end())
      s.strategies.push_back(*st);
  }
  if (s.strategies.empty()) split.fail("strategies", "names no strategy");
  std::string order = split.text(
      "order", scan_order_name(s.order),
      "regions run along rows (horizontal strips), columns, or interleaved rows (17 apart)",
      {"rows", "columns", "interleaved"});
  s.order = scan_order_from_name(order).value_or(ScanOrder::Rows);
  std::string samples = split.text(
      "samples", sample_unit_name(s.samples),
      "what the balanced split counts as a sample: every ray traced, or camera rays only",
      {"rays", "camera"});
  s.samples = sample_unit_from_name(samples).value_or(SampleUnit::Rays);

  s.settle_pct = r.section("report").real(
      "settle_pct", s.settle_pct, "%",
      "a split has settled once its max deviation stays at or below this", 0, 1000);
}

DeviceSet read_set(const toml::table* root, ConfigReadContext& ctx) {
  DeviceSet s;
  ConfigReader reader(root, "", ctx);
  read_single_keys(reader, s);
  toml::table empty;
  read_devices(root ? *root : empty, s, ctx);
  read_changes(root ? *root : empty, s, ctx);
  ctx.known.push_back("device");
  ctx.known.push_back("change");
  return s;
}

}  // namespace

DeviceSet load_device_set(const std::string& path, const std::vector<std::string>& overrides) {
  toml::table root = parse_config_file(path, "device set");
  ConfigReadContext ctx;
  ctx.file = path.empty() ? "(defaults)" : path;
  ctx.set_option = "--device-set";
  for (const std::string& assignment : overrides) apply_override(root, assignment, ctx);
  DeviceSet s = read_set(&root, ctx);
  check_unknown_keys(root, ctx);
  s.file = path;
  return s;
}

std::vector<ConfigKeyDoc> device_set_keys() {
  ConfigReadContext ctx;
  read_set(nullptr, ctx);
  return ctx.docs;
}

nlohmann::ordered_json device_set_json(const DeviceSet& s) {
  nlohmann::ordered_json j;
  j["name"] = s.name;
  j["description"] = s.description;
  j["file"] = s.file;
  const LinkConfig& l = s.flow.link;
  j["link"] = {
      {"bandwidth_gbps", l.bandwidth_gbps}, {"latency_us", l.latency_us}, {"shared", l.shared}};
  const FlowConfig& f = s.flow;
  j["flow"] = {{"raygen_ns_per_pixel", f.raygen_ns_per_pixel},
               {"filter_ns_per_pixel", f.filter_ns_per_pixel},
               {"input_bytes_per_pixel", f.input_bytes_per_pixel},
               {"bytes_per_sample", f.bytes_per_sample},
               {"bytes_per_ray", f.bytes_per_ray},
               {"output_bytes_per_pixel", f.output_bytes_per_pixel}};
  nlohmann::ordered_json names = nlohmann::ordered_json::array();
  for (SplitStrategy st : s.strategies) names.push_back(strategy_name(st));
  j["split"] = {{"strategies", names},
                {"order", scan_order_name(s.order)},
                {"samples", sample_unit_name(s.samples)}};
  j["report"] = {{"settle_pct", s.settle_pct}};
  j["device"] = nlohmann::ordered_json::array();
  for (const DeviceHardware& d : s.devices)
    j["device"].push_back({{"config", d.config}, {"set", d.sets}});
  j["change"] = nlohmann::ordered_json::array();
  for (const DeviceChange& c : s.changes)
    j["change"].push_back({{"frame", c.frame},
                           {"device", c.device},
                           {"config", c.hardware.config},
                           {"set", c.hardware.sets}});
  return j;
}

DeviceConfigs::DeviceConfigs(const DeviceSet& set, const std::vector<std::string>& hw_overrides)
    : base_(set.devices), changes_(set.changes), hw_overrides_(hw_overrides) {
  std::string file = set.file.empty() ? "device set" : set.file;
  if (base_.empty()) throw_input_error(file, "", "no devices: give [[device]] or --devices");
  for (const DeviceChange& c : changes_)
    if (c.device >= devices())
      throw_input_error(file, "",
                        fmt::format("a change at frame {} names device {}, but there "
                                    "are {} devices",
                                    c.frame, c.device, devices()));
  for (uint32_t d = 0; d < devices(); ++d) index(d, 0);  // bad configs fail before any work
  for (const DeviceChange& c : changes_) index(c.device, c.frame);
}

uint32_t DeviceConfigs::index(uint32_t device, uint32_t frame) {
  DeviceHardware h = base_.at(device);
  const DeviceChange* latest = nullptr;  // changes are sorted by frame
  for (const DeviceChange& c : changes_)
    if (c.device == device && c.frame <= frame) latest = &c;
  if (latest) {
    if (!latest->hardware.config.empty()) h.config = latest->hardware.config;
    const std::vector<std::string>& sets = latest->hardware.sets;
    h.sets.insert(h.sets.end(), sets.begin(), sets.end());
  }
  h.sets.insert(h.sets.end(), hw_overrides_.begin(), hw_overrides_.end());
  std::string label =
      h.config.empty() ? "(defaults)" : std::filesystem::path(h.config).stem().string();
  for (const std::string& s : h.sets) label += " " + s;
  std::string key = h.config + "\n" + label;
  auto it = known_.find(key);
  if (it != known_.end()) return it->second;
  configs_.push_back(load_hw_config(h.config, h.sets));
  labels_.push_back(label);
  return known_[key] = uint32_t(configs_.size() - 1);
}

}  // namespace rtsim::multi
