// Reading sweep specs and regression suites (TOML, parsed by parse_config_file in
// model/config/config_reader.h): every mistake is an InputError naming the file and the line,
// and relative paths resolve next to the file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace rtsim::reports {

struct SpecReader {
  std::string file;

  [[noreturn]] void fail(const toml::node& node, const std::string& what) const;
  // Fails on the first key of the table that is not in keys ("unknown key 'K' in WHERE").
  void only(const toml::table& table, const std::vector<std::string>& keys,
            const std::string& where) const;
  // t[key] (or the node n) as a string; def when absent.
  std::string text(const toml::table& t, const char* key, const std::string& def = "") const;
  std::string text(const toml::node* n, const char* key, const std::string& def = "") const;
  // The node as a list of strings ("key=value" overrides).
  std::vector<std::string> strings(const toml::node& n, const char* key) const;
  // The node as an integer in [lo, hi].
  int64_t integer(const toml::node& n, const char* key, int64_t lo, int64_t hi) const;
  // t[key] as an integer in [lo, hi]; def when absent.
  int64_t integer(const toml::table& t, const char* key, int64_t def, int64_t lo, int64_t hi) const;
  bool boolean(const toml::node& n, const char* key) const;
  double non_negative(const toml::node& n, const std::string& what) const;
  // Fails at n if `name` (what it names, e.g. "[[workload]] name") cannot be one component of
  // an output path (path_name_problem, traces/path_name.h).
  void path_name(const toml::node& n, const std::string& name, const std::string& what) const;
  // An existing file as an absolute path: relative to the file's folder if such a file exists,
  // else to the current folder; anything else (a built-in scene) as written. Absolute, so that
  // jobs started elsewhere (Slurm sweeps) find the same files.
  std::string resolve(const std::string& path) const;
};

}  // namespace rtsim::reports
