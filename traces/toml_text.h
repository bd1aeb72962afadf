// Every TOML document rtsim reads (hardware configs, workload specs, sweep specs, regression
// suites, device sets, --set values) is parsed here, so that one depth limit guards them all.
// toml++ builds and destroys a table per dotted part and per nested array or inline table by
// recursion, so a header of 100,000 dotted parts overflows the stack. check_toml_depth scans the
// text first (linear, no allocation) and refuses a document whose nesting exceeds kMaxTomlDepth.
#pragma once

#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace rtsim {

// The deepest nesting a document may have: the dotted parts of its table header and key, plus
// one per array or inline table around a value (rtsim's own documents nest 4 deep at most).
constexpr int kMaxTomlDepth = 64;

// Throws InputError "SOURCE: line N: nesting depth D exceeds the limit of 64 ..." for the first
// key, table header, array or inline table nested deeper than kMaxTomlDepth.
void check_toml_depth(std::string_view text, const std::string& source);

// check_toml_depth, then toml++'s parse; a syntax error is InputError "SOURCE: line N: WHAT".
toml::table parse_toml(std::string_view text, const std::string& source);

}  // namespace rtsim
