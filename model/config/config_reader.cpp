#include "model/config/config_reader.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "traces/byte_size.h"
#include "traces/error.h"
#include "traces/toml_text.h"

namespace rtsim {
namespace {

std::string line_of(const toml::node* node) {
  if (!node || !node->source().begin) return "";
  return fmt::format("line {}", node->source().begin.line);
}

std::string type_of(const toml::node& node) {
  if (node.is_string()) return "a string";
  if (node.is_integer()) return "an integer";
  if (node.is_floating_point()) return "a number";
  if (node.is_boolean()) return "a boolean";
  if (node.is_table()) return "a section";
  if (node.is_array()) return "an array";
  return "a date or time";
}

bool contains(const std::vector<std::string>& list, const std::string& item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

// An override as an error names it: cut short, so that a huge one is still a short line.
std::string shown(const std::string& assignment) {
  constexpr size_t kShown = 100;
  return assignment.size() <= kShown ? assignment : assignment.substr(0, kShown) + "...";
}

}  // namespace

ConfigReader::ConfigReader(const toml::table* table, std::string prefix, ConfigReadContext& ctx)
    : table_(table), prefix_(std::move(prefix)), ctx_(ctx) {
  if (!prefix_.empty() && !contains(ctx_.sections, prefix_)) ctx_.sections.push_back(prefix_);
}

std::string ConfigReader::full_key(const std::string& key) const {
  if (prefix_.empty()) return key;
  return key.empty() ? prefix_ : prefix_ + "." + key;
}

ConfigReader ConfigReader::section(const std::string& name) {
  const toml::node* node = table_ ? table_->get(name) : nullptr;
  if (node && !node->is_table()) fail(name, "must be a section (a table), not a value");
  return ConfigReader(node ? node->as_table() : nullptr, full_key(name), ctx_);
}

void ConfigReader::fail(const std::string& key, const std::string& what) const {
  const toml::node* node = table_ && !key.empty() ? table_->get(key) : table_;
  std::string full = ctx_.shown(full_key(key));
  std::string set = ctx_.set_place(full);
  throw_input_error(set.empty() ? ctx_.file : set, set.empty() ? line_of(node) : "",
                    fmt::format("key '{}': {}", full, what));
}

const toml::node* ConfigReader::take(const std::string& key, const char* type,
                                     const std::string& def, const char* unit, const char* desc) {
  std::string full = full_key(key);
  if (!contains(ctx_.known, full)) {
    ctx_.known.push_back(full);
    ctx_.docs.push_back({full, type, def, unit, desc});
  }
  return table_ ? table_->get(key) : nullptr;
}

void ConfigReader::record(const std::string& key, nlohmann::ordered_json value) {
  ctx_.values.emplace_back(full_key(key), std::move(value));
}

uint64_t ConfigReader::integer(const std::string& key, uint64_t def, const char* unit,
                               const char* desc, uint64_t lo, uint64_t hi) {
  const toml::node* node = take(key, "integer", std::to_string(def), unit, desc);
  uint64_t value = def;
  if (node) {
    auto v = node->value_exact<int64_t>();
    if (!v) fail(key, fmt::format("expected an integer, got {}", type_of(*node)));
    if (*v < 0 || uint64_t(*v) < lo || uint64_t(*v) > hi)
      fail(key, fmt::format("{} is out of range [{}, {}]", *v, lo, hi));
    value = uint64_t(*v);
  }
  record(key, value);
  return value;
}

uint64_t ConfigReader::size(const std::string& key, uint64_t def, const char* desc, uint64_t lo,
                            uint64_t hi) {
  const toml::node* node = take(key, "size", std::to_string(def), "bytes", desc);
  uint64_t value = def;
  if (node) {
    std::string shown;
    bool negative = false;
    if (auto text = node->value_exact<std::string>()) {
      std::string problem = byte_size_problem(*text, &value);
      if (!problem.empty()) fail(key, problem);
      shown = fmt::format("'{}' ({} bytes)", *text, value);
    } else if (auto v = node->value_exact<int64_t>()) {
      negative = *v < 0;
      value = uint64_t(*v);
      shown = std::to_string(*v);
    } else {
      fail(key, fmt::format("expected a size (bytes, or a string such as \"64K\" or \"4M\"), "
                            "got {}",
                            type_of(*node)));
    }
    if (negative || value < lo || value > hi)
      fail(key, fmt::format("{} is out of range [{}, {}]", shown, byte_size_text(lo),
                            byte_size_text(hi)));
  }
  record(key, value);
  return value;
}

std::vector<std::string> ConfigReader::strings(const std::string& key,
                                               const std::vector<std::string>& def,
                                               const char* desc) {
  std::string text;
  for (const std::string& d : def) text += (text.empty() ? "\"" : ", \"") + d + "\"";
  const toml::node* node = take(key, "array of strings", "[" + text + "]", "", desc);
  if (!node) {
    record(key, def);
    return def;
  }
  const toml::array* array = node->as_array();
  std::vector<std::string> values;
  for (size_t i = 0; array && i < array->size(); ++i) {
    auto v = array->get(i)->value_exact<std::string>();
    if (!v) break;
    values.push_back(*v);
  }
  if (!array || values.size() != array->size()) fail(key, "expected an array of strings");
  record(key, values);
  return values;
}

double ConfigReader::real(const std::string& key, double def, const char* unit, const char* desc,
                          double lo, double hi) {
  const toml::node* node = take(key, "number", fmt::format("{}", def), unit, desc);
  return number(key, node, def, lo, hi, false);
}

double ConfigReader::rate(const std::string& key, double def, const char* unit, const char* desc,
                          double lo, double hi, Zero zero) {
  std::string range =
      fmt::format("{}{} to {}", zero == Zero::NoLimit ? "0 = no limit, else " : "", lo, hi);
  const toml::node* node =
      take(key, "number", fmt::format("{}", def), unit, fmt::format("{}; {}", desc, range).c_str());
  return number(key, node, def, lo, hi, zero == Zero::NoLimit);
}

double ConfigReader::number(const std::string& key, const toml::node* node, double def, double lo,
                            double hi, bool zero_allowed) {
  double value = def;
  if (node) {
    auto v = node->value<double>();
    if (!v || !(node->is_integer() || node->is_floating_point()))
      fail(key, fmt::format("expected a number, got {}", type_of(*node)));
    bool zero = zero_allowed && *v == 0;
    if (!zero && (!std::isfinite(*v) || *v < lo || *v > hi))
      fail(key, fmt::format("{} is out of range [{}, {}]{}", *v, lo, hi,
                            zero_allowed ? " (or 0: no limit)" : ""));
    value = *v;
  }
  record(key, value);
  return value;
}

bool ConfigReader::boolean(const std::string& key, bool def, const char* desc) {
  const toml::node* node = take(key, "boolean", def ? "true" : "false", "", desc);
  bool value = def;
  if (node) {
    auto v = node->value_exact<bool>();
    if (!v) fail(key, fmt::format("expected true or false, got {}", type_of(*node)));
    value = *v;
  }
  record(key, value);
  return value;
}

std::string ConfigReader::text(const std::string& key, const std::string& def, const char* desc,
                               const std::vector<std::string>& choices) {
  std::string type = "string";
  if (!choices.empty()) {
    type = "one of";
    for (const std::string& c : choices) type += " " + c;
  }
  const toml::node* node = take(key, type.c_str(), "\"" + def + "\"", "", desc);
  std::string value = def;
  if (node) {
    auto v = node->value_exact<std::string>();
    if (!v) fail(key, fmt::format("expected a string, got {}", type_of(*node)));
    value = *v;
  }
  if (!choices.empty() && !contains(choices, value)) {
    std::string list;
    for (const std::string& c : choices) list += (list.empty() ? "" : ", ") + c;
    fail(key, fmt::format("'{}' is not one of {}", value, list));
  }
  record(key, value);
  return value;
}

toml::table parse_config_file(const std::string& path, const std::string& what) {
  if (path.empty()) return {};
  std::ifstream in(path);
  if (!in) throw_input_error(path, "", "cannot open the " + what);
  std::stringstream text;
  text << in.rdbuf();
  return parse_toml(text.str(), path);
}

std::string ConfigReadContext::shown(const std::string& key) const {
  for (const auto& [read, written] : aliases)
    if (key.compare(0, read.size(), read) == 0) return written + key.substr(read.size());
  return key;
}

std::string ConfigReadContext::set_place(const std::string& read_key) const {
  std::string key = shown(read_key);
  for (auto it = set_assignments.rbegin(); it != set_assignments.rend(); ++it)
    if (it->compare(0, key.size() + 1, key + "=") == 0) return set_option + " " + shown(*it);
  return "";
}

std::string ConfigReadContext::set_places() const {
  std::string places;
  for (const std::string& assignment : set_assignments)
    places += (places.empty() ? "" : " ") + set_option + " " + shown(assignment);
  return places;
}

void apply_override(toml::table& root, const std::string& assignment, ConfigReadContext& ctx) {
  std::string place = ctx.set_option + " " + shown(assignment);
  size_t eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) throw_input_error(place, "", "expected KEY=VALUE");
  check_toml_depth(assignment, place);  // "KEY=VALUE" is a line of TOML
  std::string key = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  // The value in TOML syntax; anything that does not parse is taken as a string.
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + text);
  } catch (const toml::parse_error&) {
  }
  toml::table* table = &root;
  size_t start = 0;
  for (size_t dot = key.find('.'); dot != std::string::npos; dot = key.find('.', start)) {
    std::string part = key.substr(start, dot - start);
    toml::node* node = table->get(part);
    if (!node) node = &table->insert_or_assign(part, toml::table{}).first->second;
    if (!node->is_table())
      throw_input_error(place, "", fmt::format("'{}' is a value, not a section", part));
    table = node->as_table();
    start = dot + 1;
  }
  std::string leaf = key.substr(start);
  if (const toml::node* value = parsed.get("v"); value && !value->is_table())
    table->insert_or_assign(leaf, *value);
  else
    table->insert_or_assign(leaf, text);
  ctx.set_assignments.push_back(assignment);
}

namespace {

struct Unknown {
  uint32_t line = 0;
  std::string key, section;
};

void find_unknown(const toml::table& table, const std::string& prefix, const ConfigReadContext& ctx,
                  std::vector<Unknown>& out) {
  for (auto&& [name, node] : table) {
    std::string key(name.str());
    std::string full = prefix.empty() ? key : prefix + "." + key;
    std::string written = ctx.shown(full);
    uint32_t line = name.source().begin ? name.source().begin.line : 0;
    if (node.is_table() && contains(ctx.sections, full)) {
      find_unknown(*node.as_table(), full, ctx, out);
    } else if (!contains(ctx.known, full)) {
      out.push_back({line, written, ctx.shown(prefix)});
    }
  }
}

}  // namespace

void check_unknown_keys(const toml::table& root, const ConfigReadContext& ctx) {
  std::vector<Unknown> unknown;
  find_unknown(root, "", ctx, unknown);
  if (unknown.empty()) return;
  // Overrides first (they have no line), then the file's first unknown key by line.
  auto set = std::find_if(unknown.begin(), unknown.end(),
                          [&](const Unknown& u) { return !ctx.set_place(u.key).empty(); });
  const Unknown& u = set != unknown.end()
                         ? *set
                         : *std::min_element(unknown.begin(), unknown.end(),
                                             [](auto& a, auto& b) { return a.line < b.line; });
  std::string known;
  for (const ConfigKeyDoc& d : ctx.docs) {
    std::string key = ctx.shown(d.key);
    std::string section = key.substr(0, key.rfind('.') == std::string::npos ? 0 : key.rfind('.'));
    if (section == u.section)
      known +=
          (known.empty() ? "" : ", ") + key.substr(u.section.empty() ? 0 : u.section.size() + 1);
  }
  std::string what = fmt::format("unknown key '{}'", u.key);
  if (!known.empty())
    what += fmt::format(" (keys of [{}]: {})", u.section.empty() ? "top level" : u.section, known);
  if (set != unknown.end()) throw_input_error(ctx.set_place(u.key), "", what);
  throw_input_error(ctx.file, u.line ? fmt::format("line {}", u.line) : "", what);
}

}  // namespace rtsim
