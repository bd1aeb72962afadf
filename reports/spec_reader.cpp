#include "reports/spec_reader.h"

#include <algorithm>
#include <filesystem>
#include <optional>

#include <fmt/core.h>

#include "traces/error.h"
#include "traces/path_name.h"

namespace rtsim::reports {
namespace fs = std::filesystem;

void SpecReader::fail(const toml::node& node, const std::string& what) const {
  throw_input_error(file, fmt::format("line {}", node.source().begin.line), what);
}

void SpecReader::only(const toml::table& table, const std::vector<std::string>& keys,
                      const std::string& where) const {
  for (const auto& [key, node] : table)
    if (std::find(keys.begin(), keys.end(), std::string(key.str())) == keys.end())
      fail(node, fmt::format("unknown key '{}' in {}", key.str(), where));
}

std::string SpecReader::text(const toml::table& t, const char* key, const std::string& def) const {
  return text(t.get(key), key, def);
}

std::string SpecReader::text(const toml::node* n, const char* key, const std::string& def) const {
  if (!n) return def;
  if (!n->is_string()) fail(*n, fmt::format("'{}' must be a string", key));
  return std::string(*n->value<std::string>());
}

std::vector<std::string> SpecReader::strings(const toml::node& n, const char* key) const {
  std::vector<std::string> out;
  const toml::array* list = n.as_array();
  if (!list) fail(n, fmt::format("'{}' must be a list of \"key=value\" strings", key));
  for (const toml::node& item : *list) out.push_back(text(&item, key));
  return out;
}

int64_t SpecReader::integer(const toml::node& n, const char* key, int64_t lo, int64_t hi) const {
  std::optional<int64_t> v = n.is_integer() ? n.value<int64_t>() : std::nullopt;
  if (!v || *v < lo || *v > hi)
    fail(n, fmt::format("'{}' must be an integer {} to {}", key, lo, hi));
  return *v;
}

int64_t SpecReader::integer(const toml::table& t, const char* key, int64_t def, int64_t lo,
                            int64_t hi) const {
  const toml::node* n = t.get(key);
  return n ? integer(*n, key, lo, hi) : def;
}

bool SpecReader::boolean(const toml::node& n, const char* key) const {
  if (!n.is_boolean()) fail(n, fmt::format("'{}' must be true or false", key));
  return *n.value<bool>();
}

double SpecReader::non_negative(const toml::node& n, const std::string& what) const {
  std::optional<double> v = n.value<double>();
  if (!v || *v < 0) fail(n, what + " must be a number >= 0");
  return *v;
}

void SpecReader::path_name(const toml::node& n, const std::string& name,
                           const std::string& what) const {
  std::string problem = path_name_problem(name);
  if (!problem.empty())
    fail(n, what + ": " + problem + " (it names a folder of the output: one path component)");
}

std::string SpecReader::resolve(const std::string& path) const {
  if (path.empty()) return path;
  fs::path beside = fs::path(file).parent_path() / path;
  if (fs::exists(beside)) return fs::absolute(beside).lexically_normal().string();
  return fs::exists(path) ? fs::absolute(path).lexically_normal().string() : path;
}

}  // namespace rtsim::reports
