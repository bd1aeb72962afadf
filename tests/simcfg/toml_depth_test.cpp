// The depth limit every TOML read goes through (traces/toml_text.h): documents nested past it are
// refused with the source, line and depth before toml++ parses them; brackets, braces and dots
// inside strings and comments do not count, so valid documents of any shape still parse.
#include <gtest/gtest.h>

#include <string>

#include "traces/error.h"
#include "traces/toml_text.h"

namespace rtsim {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_toml(text, "doc.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string repeat(const std::string& part, int n) {
  std::string text;
  for (int i = 0; i < n; ++i) text += part;
  return text;
}

TEST(TomlDepth, RefusesDeepHeadersKeysArraysAndInlineTables) {
  std::string header = "[a" + repeat(".a", 99999) + "]\n";
  EXPECT_EQ(error_of("x = 1\n\n" + header),
            "doc.toml: line 3: nesting depth 100000 exceeds the limit of 64 (dotted key parts, "
            "arrays and inline tables together)");
  EXPECT_EQ(error_of("[[t" + repeat(".t", 64) + "]]\n"),
            "doc.toml: line 1: nesting depth 65 exceeds the limit of 64 (dotted key parts, arrays "
            "and inline tables together)");
  EXPECT_NE(error_of("a" + repeat(".a", 64) + " = 1\n").find("line 1: nesting depth 65"),
            std::string::npos);
  // The header's parts and the key's add up.
  EXPECT_NE(error_of("[" + repeat("a.", 39) + "a]\n" + repeat("b.", 24) + "b = 1\n")
                .find("line 2: nesting depth 65"),
            std::string::npos);
  EXPECT_NE(error_of("x = " + repeat("[", 100000)).find("line 1: nesting depth 65"),
            std::string::npos);
  EXPECT_NE(error_of("x = [\n" + repeat("[", 63) + "\n").find("line 2: nesting depth 65"),
            std::string::npos);
  EXPECT_NE(error_of("x = " + repeat("{a = ", 32)).find("nesting depth 65"), std::string::npos);
  EXPECT_NE(error_of("x = [" + repeat("{a = [", 21)).find("nesting depth 65"), std::string::npos);
}

TEST(TomlDepth, TakesDocumentsAtTheLimitAndStringsAsText) {
  EXPECT_EQ(error_of("a" + repeat(".a", 63) + " = 1\n"), "(no error)");
  EXPECT_EQ(error_of("x = " + repeat("[", 63) + repeat("]", 63) + "\n"), "(no error)");
  std::string deep = repeat("[", 1000) + repeat("{", 1000) + repeat(".", 1000);
  EXPECT_EQ(error_of("a = \"" + deep + "\"\n"), "(no error)");
  EXPECT_EQ(error_of("a = '" + deep + "'\n"), "(no error)");
  EXPECT_EQ(error_of("a = \"\"\"\n" + deep + "\n\\\"\"\" \"\"\"\n[t]\nb = 1\n"), "(no error)");
  EXPECT_EQ(error_of("a = '''\n" + deep + "\n'''\n"), "(no error)");
  EXPECT_EQ(error_of("# " + deep + "\na = 1 # " + deep + "\n"), "(no error)");
  EXPECT_EQ(error_of("\"" + deep + "x\" = 1\n['" + deep + "']\nb = [\"]\", '[', {c = \"}\"}]\n"),
            "(no error)");
  EXPECT_EQ(error_of("[a.b]\nc = {d.e = [1, [2, {f = 3}]], g = 4}\nh.i = 5\n"), "(no error)");
}

TEST(TomlDepth, SyntaxErrorsNameSourceAndLine) {
  EXPECT_NE(error_of("a = 1\nb = \n").find("doc.toml: line 2: "), std::string::npos);
  EXPECT_NE(error_of("a = \"open\n").find("doc.toml: line 1: "), std::string::npos);
}

}  // namespace
}  // namespace rtsim
