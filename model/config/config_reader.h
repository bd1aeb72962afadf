// Typed reads of hardware-config keys that document themselves: each read names its key, its
// default, unit and one-line description, checks type and range, records the key as known and
// records the value it resolved to. After all reads, finish() reports the first unknown key in
// the file (with its line) or among the --set overrides. Reading an empty document lists every
// key with its default (the documentation of the config) and, with other defaults, writes out
// a resolved config.
#pragma once

#include <toml++/toml.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace rtsim {

// The slowest data port or crossbar link: a link books a transfer cycle by cycle
// (model/mem/crossbar.h), so a 4 KB line at 1 byte a cycle already costs 4,096 steps; slower
// ports made runs endless, and 1e-30 pushed event times past what SystemC represents.
constexpr double kMinPortBytesPerCycle = 1;
constexpr double kMaxBytesPerCycle = 1e6;

struct ConfigKeyDoc {
  std::string key;            // dotted: "rt.l1.size_bytes"
  std::string type;           // integer, size, number, boolean, string
  std::string default_value;  // as TOML writes it
  std::string unit;
  std::string description;
};

struct ConfigReadContext {
  std::string file;                          // for error messages
  std::string set_option = "--set";          // the command-line option that overrides keys
  std::vector<std::string> set_assignments;  // "KEY=VALUE" given with it, in order
  std::vector<ConfigKeyDoc> docs;            // every key read, in read order, with its default
  std::vector<std::pair<std::string, nlohmann::ordered_json>> values;  // resolved, read order
  std::vector<std::string> known;                                      // every key read, dotted
  std::vector<std::string> sections;  // every section opened, dotted
  // (read, written) key prefixes: keys read under one name that the user wrote under another
  // (the shorthand [rt.l1], [xbar] and [l2] for memory.l1 and memory.l2), named as written.
  std::vector<std::pair<std::string, std::string>> aliases;

  // A key (or a text naming keys) as the user wrote it.
  std::string shown(const std::string& key) const;

  // Where an error about key points: "--set KEY=VALUE" (its last override), or empty if the
  // key was not overridden.
  std::string set_place(const std::string& key) const;
  // Every override as given ("--set A=1 --set B=2").
  std::string set_places() const;
};

class ConfigReader {
 public:
  // table may be null: an absent section, every read returns its default.
  ConfigReader(const toml::table* table, std::string prefix, ConfigReadContext& ctx);

  ConfigReader section(const std::string& name);
  uint64_t integer(const std::string& key, uint64_t def, const char* unit, const char* desc,
                   uint64_t lo, uint64_t hi);
  // A capacity in bytes, of type "size": an integer, or a string with a binary suffix ("64K",
  // "4M", "1GiB"; traces/byte_size.h). Bandwidths are rates, not sizes.
  uint64_t size(const std::string& key, uint64_t def, const char* desc, uint64_t lo, uint64_t hi);
  double real(const std::string& key, double def, const char* unit, const char* desc, double lo,
              double hi);
  // A rate (a bandwidth): lo to hi, or 0 for no limit where zero is Zero::NoLimit. Its floor is
  // what keeps a transfer's cycles few enough to simulate and within SystemC's time; the
  // description gains the range, so --list-keys and model/SIM-REFERENCE.md state it.
  enum class Zero : uint8_t { Refused, NoLimit };
  double rate(const std::string& key, double def, const char* unit, const char* desc, double lo,
              double hi, Zero zero);
  bool boolean(const std::string& key, bool def, const char* desc);
  std::string text(const std::string& key, const std::string& def, const char* desc,
                   const std::vector<std::string>& choices = {});
  std::vector<std::string> strings(const std::string& key, const std::vector<std::string>& def,
                                   const char* desc);
  // Throws InputError naming this section's key (or the section itself) and its line.
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;

 private:
  const toml::node* take(const std::string& key, const char* type, const std::string& def,
                         const char* unit, const char* desc);
  void record(const std::string& key, nlohmann::ordered_json value);
  // The number at node (def if absent) in [lo, hi], or 0 if zero_allowed.
  double number(const std::string& key, const toml::node* node, double def, double lo, double hi,
                bool zero_allowed);
  std::string full_key(const std::string& key) const;

  const toml::table* table_;
  std::string prefix_;
  ConfigReadContext& ctx_;
};

// The TOML document of a config file; an empty table when path is empty (built-in defaults).
// InputError names the file ("cannot open the WHAT") or the line of a syntax error.
toml::table parse_config_file(const std::string& path, const std::string& what);

// Applies "key=value" (value in TOML syntax; a bare word is a string) to the document,
// creating sections as needed, and notes it in ctx.set_assignments; throws InputError naming
// ctx.set_option for a malformed one or one nested deeper than kMaxTomlDepth
// (traces/toml_text.h).
void apply_override(toml::table& root, const std::string& assignment, ConfigReadContext& ctx);

// Throws InputError for the first key of the document (by line) or of --set that was never
// read, naming the file, the line and the keys that section does know.
void check_unknown_keys(const toml::table& root, const ConfigReadContext& ctx);

}  // namespace rtsim
