// Typed reads of TOML keys that document themselves: each read names the key, its default,
// unit and description, returns the value (or the default), checks type and range, and
// records the key as known. After all reads, finish() reports the first unknown key with its
// line. Reading an empty document in documenting mode lists every key (spec_key_docs()).
#pragma once

#include <toml++/toml.h>

#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "workloads/pipeline/spec.h"

namespace rtsim::pipeline {

class SpecReader;

struct SpecReadContext {
  std::string file;
  bool documenting = false;  // arrays of tables yield one empty entry, so their keys are listed
  std::vector<KeyDoc> docs;
  std::vector<std::unique_ptr<SpecReader>> readers;

  void document(KeyDoc doc);
  void finish();  // throws InputError for the first unknown key in file order
};

class SpecReader {
 public:
  // table may be null (an absent section: every read returns its default).
  SpecReader(const toml::table* table, std::string prefix, SpecReadContext& ctx);

  double real(const std::string& key, double def, const char* unit, const char* desc, double lo,
              double hi);
  std::optional<double> real_or_auto(const std::string& key, const char* auto_meaning,
                                     const char* unit, const char* desc, double lo, double hi);
  int64_t integer(const std::string& key, int64_t def, const char* unit, const char* desc,
                  int64_t lo, int64_t hi);
  bool boolean(const std::string& key, bool def, const char* desc);
  std::string text(const std::string& key, const std::string& def, const char* desc,
                   const std::vector<std::string>& choices = {});
  glm::vec3 vec3(const std::string& key, glm::vec3 def, const char* unit, const char* desc);
  std::optional<glm::vec3> vec3_or_auto(const std::string& key, const char* auto_meaning,
                                        const char* unit, const char* desc);
  // Optional keys without a default (material rules): nullopt when absent; `absent` says what
  // that means in the documentation.
  std::optional<double> maybe_real(const std::string& key, const char* unit, const char* desc,
                                   double lo, double hi, const char* absent = "(scene's)");
  std::optional<glm::vec3> maybe_vec3(const std::string& key, const char* unit, const char* desc,
                                      const char* absent = "(scene's)");

  SpecReader& section(const std::string& key, const char* desc);
  std::vector<SpecReader*> sections(const std::string& key, const char* desc);

  bool has(const std::string& key) const;
  bool documenting() const { return ctx_.documenting; }
  // Throws InputError naming this key (or the section, if key is empty) and its line.
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;
  // "line N" of this table in the file ("" if built in code).
  std::string where() const { return line_of(table_); }
  std::string full_key(const std::string& key) const;

 private:
  friend struct SpecReadContext;
  const toml::node* take(const std::string& key, const char* type, const std::string& def,
                         const char* unit, const char* desc);
  std::string line_of(const toml::node* node) const;
  double check_real(const std::string& key, const toml::node& node, double lo, double hi) const;
  glm::vec3 to_vec3(const std::string& key, const toml::node& node) const;

  const toml::table* table_;
  std::string prefix_;
  SpecReadContext& ctx_;
  std::vector<std::string> known_;
};

}  // namespace rtsim::pipeline
