// One check of `rtsim validate` (model/VALIDATION.md): what it checks, where its expected value
// comes from (a formula of the config, a paper's table or abstract, a datasheet), the band the
// measured value must fall in, and what to look at when it does not.
#pragma once

#include <cmath>
#include <string>
#include <vector>

namespace rtsim::validation {

struct Check {
  std::string id;             // suite.name, e.g. "ladder.l1_hit"
  std::string suite;          // closed_form, published, presets
  std::string title;          // what it checks, one line
  std::string source{};       // formula, paper (table or figure) or datasheet
  std::string unit{};         // of expected, lo, hi and measured
  double expected = NAN;      // the closed form or the published figure (NaN: a band only)
  double lo = NAN, hi = NAN;  // pass band, inclusive; NaN: a figure reported, not judged
  double measured = NAN;
  std::string detail{};   // how measured: the runs and the counters
  std::string look_at{};  // where to look when it fails
  std::string
      skipped{};  // not run, and why (a missing scene); such a check neither passes nor fails

  bool ran() const { return skipped.empty(); }
  bool judged() const { return ran() && !std::isnan(lo); }
  bool passed() const { return judged() && measured >= lo && measured <= hi; }
  bool failed() const { return judged() && !passed(); }
  // skipped, info (reported, not judged), pass or fail
  const char* status() const {
    return !ran() ? "skipped" : !judged() ? "info" : passed() ? "pass" : "fail";
  }
};

// A band of +-tolerance (a fraction) around expected.
inline void set_band(Check& check, double expected, double tolerance) {
  check.expected = expected;
  check.lo = expected * (1 - tolerance);
  check.hi = expected * (1 + tolerance);
}

inline void set_exact(Check& check, double expected, double slack = 0) {
  check.expected = expected;
  check.lo = expected - slack;
  check.hi = expected + slack;
}

}  // namespace rtsim::validation
