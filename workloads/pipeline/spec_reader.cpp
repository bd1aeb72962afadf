#include "workloads/pipeline/spec_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "traces/error.h"

namespace rtsim::pipeline {
namespace {

std::string format_vec3(glm::vec3 v) {
  return fmt::format("[{}, {}, {}]", v.x, v.y, v.z);
}

std::string range_text(double lo, double hi) {
  if (hi == INFINITY) return fmt::format("at least {}", lo);
  return fmt::format("in [{}, {}]", lo, hi);
}

}  // namespace

void SpecReadContext::document(KeyDoc doc) {
  for (auto& d : docs)
    if (d.key == doc.key) return;
  docs.push_back(std::move(doc));
}

void SpecReadContext::finish() {
  if (documenting) return;
  uint32_t first_line = 0;
  std::string first_key;
  for (auto& reader : readers) {
    if (!reader->table_) continue;
    for (auto&& [key, node] : *reader->table_) {
      std::string name(key.str());
      if (std::find(reader->known_.begin(), reader->known_.end(), name) != reader->known_.end())
        continue;
      uint32_t line = key.source().begin.line;
      if (first_key.empty() || line < first_line) {
        first_line = line;
        first_key = reader->full_key(name);
      }
    }
  }
  if (!first_key.empty())
    throw_input_error(file, fmt::format("line {}", first_line),
                      fmt::format("unknown key '{}'", first_key));
}

SpecReader::SpecReader(const toml::table* table, std::string prefix, SpecReadContext& ctx)
    : table_(table), prefix_(std::move(prefix)), ctx_(ctx) {}

std::string SpecReader::full_key(const std::string& key) const {
  if (prefix_.empty()) return key;
  return key.empty() ? prefix_ : prefix_ + "." + key;
}

std::string SpecReader::line_of(const toml::node* node) const {
  if (!node || !node->source().begin) return "";
  return fmt::format("line {}", node->source().begin.line);
}

bool SpecReader::has(const std::string& key) const {
  return table_ && table_->contains(key);
}

void SpecReader::fail(const std::string& key, const std::string& what) const {
  const toml::node* node = table_ && !key.empty() ? table_->get(key) : nullptr;
  if (!node && !prefix_.empty()) node = table_;  // an absent key: the line of its table
  throw_input_error(ctx_.file, line_of(node), fmt::format("key '{}': {}", full_key(key), what));
}

const toml::node* SpecReader::take(const std::string& key, const char* type, const std::string& def,
                                   const char* unit, const char* desc) {
  ctx_.document({full_key(key), type, def, unit, desc});
  known_.push_back(key);
  return table_ ? table_->get(key) : nullptr;
}

double SpecReader::real(const std::string& key, double def, const char* unit, const char* desc,
                        double lo, double hi) {
  const toml::node* node = take(key, "number", fmt::format("{}", def), unit, desc);
  return node ? check_real(key, *node, lo, hi) : def;
}

std::optional<double> SpecReader::maybe_real(const std::string& key, const char* unit,
                                             const char* desc, double lo, double hi,
                                             const char* absent) {
  const toml::node* node = take(key, "number", absent, unit, desc);
  if (!node) return std::nullopt;
  return check_real(key, *node, lo, hi);
}

double SpecReader::check_real(const std::string& key, const toml::node& node, double lo,
                              double hi) const {
  auto value = node.value<double>();
  if (!value || !std::isfinite(*value) || node.is_boolean()) fail(key, "expected a finite number");
  if (*value < lo || *value > hi) fail(key, fmt::format("must be {}", range_text(lo, hi)));
  return *value;
}

std::optional<double> SpecReader::real_or_auto(const std::string& key, const char* auto_meaning,
                                               const char* unit, const char* desc, double lo,
                                               double hi) {
  const toml::node* node =
      take(key, "number or \"auto\"", fmt::format("\"auto\" ({})", auto_meaning), unit, desc);
  if (!node || node->value<std::string>() == "auto") return std::nullopt;
  if (node->is_string()) fail(key, "expected a number or \"auto\"");
  return check_real(key, *node, lo, hi);
}

int64_t SpecReader::integer(const std::string& key, int64_t def, const char* unit, const char* desc,
                            int64_t lo, int64_t hi) {
  const toml::node* node = take(key, "integer", fmt::format("{}", def), unit, desc);
  if (!node) return def;
  auto value = node->value_exact<int64_t>();
  if (!value) fail(key, "expected an integer");
  if (*value < lo || *value > hi) fail(key, fmt::format("must be in [{}, {}]", lo, hi));
  return *value;
}

bool SpecReader::boolean(const std::string& key, bool def, const char* desc) {
  const toml::node* node = take(key, "boolean", def ? "true" : "false", "", desc);
  if (!node) return def;
  auto value = node->value_exact<bool>();
  if (!value) fail(key, "expected true or false");
  return *value;
}

std::string SpecReader::text(const std::string& key, const std::string& def, const char* desc,
                             const std::vector<std::string>& choices) {
  std::string type = "string";
  if (!choices.empty()) type = fmt::format("one of \"{}\"", fmt::join(choices, "\", \""));
  const toml::node* node = take(key, type.c_str(), def.empty() ? "" : "\"" + def + "\"", "", desc);
  if (!node) return def;
  auto value = node->value_exact<std::string>();
  if (!value) fail(key, "expected a string");
  if (!choices.empty() && std::find(choices.begin(), choices.end(), *value) == choices.end())
    fail(key, fmt::format("expected {}, got \"{}\"", type, *value));
  return *value;
}

glm::vec3 SpecReader::to_vec3(const std::string& key, const toml::node& node) const {
  const toml::array* array = node.as_array();
  if (!array || array->size() != 3) fail(key, "expected an array of 3 numbers");
  glm::vec3 v;
  for (int i = 0; i < 3; ++i) {
    auto x = array->get(i)->value<double>();
    if (!x || !(std::fabs(*x) <= std::numeric_limits<float>::max()))
      fail(key, "expected an array of 3 finite numbers (within a float's range)");
    v[i] = static_cast<float>(*x);
  }
  return v;
}

glm::vec3 SpecReader::vec3(const std::string& key, glm::vec3 def, const char* unit,
                           const char* desc) {
  const toml::node* node = take(key, "[x, y, z]", format_vec3(def), unit, desc);
  return node ? to_vec3(key, *node) : def;
}

std::optional<glm::vec3> SpecReader::maybe_vec3(const std::string& key, const char* unit,
                                                const char* desc, const char* absent) {
  const toml::node* node = take(key, "[x, y, z]", absent, unit, desc);
  if (!node) return std::nullopt;
  return to_vec3(key, *node);
}

std::optional<glm::vec3> SpecReader::vec3_or_auto(const std::string& key, const char* auto_meaning,
                                                  const char* unit, const char* desc) {
  const toml::node* node =
      take(key, "[x, y, z] or \"auto\"", fmt::format("\"auto\" ({})", auto_meaning), unit, desc);
  if (!node || node->value<std::string>() == "auto") return std::nullopt;
  if (node->is_string()) fail(key, "expected [x, y, z] or \"auto\"");
  return to_vec3(key, *node);
}

SpecReader& SpecReader::section(const std::string& key, const char* desc) {
  const toml::node* node = take(key, "table", "", "", desc);
  if (node && !node->is_table()) fail(key, "expected a table");
  const toml::table* table = node ? node->as_table() : nullptr;
  ctx_.readers.push_back(std::make_unique<SpecReader>(table, full_key(key), ctx_));
  return *ctx_.readers.back();
}

std::vector<SpecReader*> SpecReader::sections(const std::string& key, const char* desc) {
  const toml::node* node = take(key, "array of tables", "", "", desc);
  std::vector<SpecReader*> out;
  std::string prefix = full_key(key) + "[]";
  if (!node) {
    if (ctx_.documenting) {
      ctx_.readers.push_back(std::make_unique<SpecReader>(nullptr, prefix, ctx_));
      out.push_back(ctx_.readers.back().get());
    }
    return out;
  }
  const toml::array* array = node->as_array();
  if (!array || !array->is_array_of_tables())
    fail(key, fmt::format("expected an array of tables ([[{}]])", full_key(key)));
  for (const toml::node& entry : *array) {
    ctx_.readers.push_back(std::make_unique<SpecReader>(entry.as_table(), prefix, ctx_));
    out.push_back(ctx_.readers.back().get());
  }
  return out;
}

}  // namespace rtsim::pipeline
