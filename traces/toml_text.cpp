#include "traces/toml_text.h"

#include <vector>

#include <fmt/core.h>

#include "traces/error.h"

namespace rtsim {
namespace {

// One pass over the text, tracking only what nests: table headers, keys (their dotted parts),
// arrays and inline tables; strings and comments are skipped, everything else ignored. It need
// not judge the syntax (toml++ does that next), only never undercount a valid document's depth.
class DepthScan {
 public:
  DepthScan(std::string_view text, const std::string& source) : text_(text), source_(source) {}

  void run() {
    while (at_ < text_.size()) {
      char c = text_[at_];
      if (c == '\n' || c == ' ' || c == '\t' || c == '\r') {
        skip_space();
      } else if (c == '#') {
        while (at_ < text_.size() && text_[at_] != '\n') ++at_;
      } else if (expect_key_ && open_.empty() && c == '[') {
        header_ = dotted_parts(']');
        check(header_);
      } else if (expect_key_ && c != '}') {
        key_depth_ = (open_.empty() ? header_ : open_.back().depth) + dotted_parts('=');
        check(key_depth_);
        expect_key_ = false;
      } else {
        value(c);
      }
    }
  }

 private:
  struct Open {
    int depth;
    bool array;  // else an inline table
  };

  void skip_space() {
    if (text_[at_++] != '\n') return;
    ++line_;
    if (open_.empty()) expect_key_ = true;  // a new line at the top level starts a key
  }

  void value(char c) {
    if (c == '"' || c == '\'') return skip_string();
    ++at_;
    if (c == '[' || c == '{') {
      // An array's elements, or an inline table's keys, sit one deeper than what holds them.
      int here = !open_.empty() && open_.back().array ? open_.back().depth : key_depth_;
      open_.push_back({here + 1, c == '['});
      check(here + 1);
      expect_key_ = c == '{';
    } else if ((c == ']' || c == '}') && !open_.empty()) {
      open_.pop_back();
      expect_key_ = false;
    } else if (c == ',' && !open_.empty() && !open_.back().array) {
      expect_key_ = true;
    }
  }

  // A header ("[a.b]", "[[a.b]]") or a key ("a.b =") up to `end` (consumed) or the line's end:
  // its dotted parts.
  int dotted_parts(char end) {
    int parts = 1;
    while (at_ < text_.size() && text_[at_] == '[') ++at_;
    while (at_ < text_.size() && text_[at_] != '\n') {
      char c = text_[at_];
      if (c == '"' || c == '\'') {
        skip_string();
        continue;
      }
      ++at_;
      if (c == end) break;
      if (c == '.') ++parts;
    }
    while (end == ']' && at_ < text_.size() && text_[at_] == ']') ++at_;
    return parts;
  }

  // A basic or literal string, on one line or (tripled quotes) several.
  void skip_string() {
    char quote = text_[at_];
    bool multiline = tripled(quote);
    at_ += multiline ? 3 : 1;
    while (at_ < text_.size()) {
      char c = text_[at_];
      if (c == '\n') {
        if (!multiline) return;  // unterminated: toml++ will say so
        ++line_;
      }
      if (c == '\\' && quote == '"') {  // an escape: skip the next character, unless a line end
        if (++at_ < text_.size() && text_[at_] != '\n') ++at_;
        continue;
      }
      if (c == quote && (!multiline || tripled(quote))) {
        at_ += multiline ? 3 : 1;
        return;
      }
      ++at_;
    }
  }

  bool tripled(char quote) const {
    return text_.substr(at_, 3) == (quote == '"' ? "\"\"\"" : "'''");
  }

  void check(int depth) const {
    if (depth <= kMaxTomlDepth) return;
    throw_input_error(source_, fmt::format("line {}", line_),
                      fmt::format("nesting depth {} exceeds the limit of {} (dotted key parts, "
                                  "arrays and inline tables together)",
                                  depth, kMaxTomlDepth));
  }

  std::string_view text_;
  const std::string& source_;
  size_t at_ = 0;
  int line_ = 1;
  int header_ = 0;     // dotted parts of the current table header
  int key_depth_ = 0;  // depth of the last key read
  bool expect_key_ = true;
  std::vector<Open> open_;  // arrays and inline tables open around the scan
};

}  // namespace

void check_toml_depth(std::string_view text, const std::string& source) {
  DepthScan(text, source).run();
}

toml::table parse_toml(std::string_view text, const std::string& source) {
  check_toml_depth(text, source);
  try {
    return toml::parse(text, std::string_view(source));
  } catch (const toml::parse_error& e) {
    throw_input_error(source, fmt::format("line {}", e.source().begin.line),
                      std::string(e.description()));
  }
}

}  // namespace rtsim
