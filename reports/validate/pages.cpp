// The pages of `rtsim validate`: one row per check everywhere; the HTML page adds, per suite,
// a chart of each measured value against its band, as inline SVG (it opens offline).
#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/core.h>

#include "reports/page_util.h"
#include "reports/validate/suite.h"
#include "traces/text_table.h"

namespace rtsim::validation {
namespace {

using reports::html_escape;

// Escaped for an attribute in single quotes as well as for text.
std::string attr(const std::string& text) {
  std::string out;
  for (char c : html_escape(text)) out += c == '\'' ? std::string("&#39;") : std::string(1, c);
  return out;
}

std::string status(const Check& c) {
  return c.failed() ? "FAIL" : c.status();
}

std::string band(const Check& c) {
  if (!c.ran() || std::isnan(c.lo)) return "-";
  if (c.lo == c.hi) return "= " + show_value(c.lo);
  if (std::isinf(c.hi)) return ">= " + show_value(c.lo);
  return show_value(c.lo) + " .. " + show_value(c.hi);
}

std::vector<std::vector<std::string>> rows(const SuiteResult& r) {
  std::vector<std::vector<std::string>> out{{"check", "status", "measured", "expected", "unit"}};
  for (const Check& c : r.checks)
    out.push_back({c.id, status(c), c.ran() ? show_value(c.measured) : "-", band(c), c.unit});
  return out;
}

std::string summary(const SuiteResult& r) {
  return fmt::format("{} checks on config {}{}: {} passed, {} failed, {} skipped, {} reported",
                     r.checks.size(), r.config_name, r.quick ? " (quick)" : "", r.passed(),
                     r.failed(), r.skipped(), r.reported());
}

// Suites in the order their first check appears.
std::vector<std::string> suites(const SuiteResult& r) {
  std::vector<std::string> out;
  for (const Check& c : r.checks)
    if (std::find(out.begin(), out.end(), c.suite) == out.end()) out.push_back(c.suite);
  return out;
}

// What a check's values are shown against: its expected value, else its band's middle, else
// the bound of an open band.
double reference(const Check& c) {
  if (std::isfinite(c.expected) && c.expected != 0) return c.expected;
  return std::isfinite(c.hi) ? (c.lo + c.hi) / 2 : c.lo;
}

// Each check's measured value and band over its reference (1 = the expected value).
std::string band_chart(const SuiteResult& r, const std::string& suite) {
  std::vector<const Check*> shown;
  for (const Check& c : r.checks)
    if (c.suite == suite && c.judged() && reference(c) > 0) shown.push_back(&c);
  if (shown.empty()) return "";
  double lo = 0.9, hi = 1.1;
  for (const Check* c : shown)
    for (double v : {c->lo, c->hi, c->measured})
      if (std::isfinite(v)) {
        lo = std::min(lo, v / reference(*c));
        hi = std::max(hi, v / reference(*c));
      }
  const double left = 190, width = 420, row = 22;
  double height = row * double(shown.size()) + 40;
  auto x = [&](double ratio) { return left + (ratio - lo) / (hi - lo) * width; };
  std::string title = "Measured against the pass band, suite " + suite;
  std::string svg = fmt::format(
      "<svg xmlns='http://www.w3.org/2000/svg' width='{}' height='{}' role='img' "
      "aria-label='{}'><title>{}</title>",
      left + width + 20, height, attr(title), attr(title));
  svg += fmt::format(
      "<line x1='{0}' x2='{0}' y1='0' y2='{1}' stroke='#888' "
      "stroke-dasharray='3,3'/>",
      x(1.0), height - 30);
  for (size_t i = 0; i < shown.size(); ++i) {
    const Check& c = *shown[i];
    double y = row * double(i) + 14;
    svg += fmt::format("<text x='{}' y='{}' font-size='11' text-anchor='end'>{}</text>", left - 6,
                       y + 4, html_escape(c.id));
    double b0 = x(c.lo / reference(c));
    double b1 = std::isinf(c.hi) ? left + width : x(c.hi / reference(c));
    svg += fmt::format("<rect x='{}' y='{}' width='{}' height='10' fill='#cfe3cf'/>", b0, y - 5,
                       std::max(2.0, b1 - b0));
    if (!std::isfinite(c.measured)) continue;
    svg += fmt::format("<circle cx='{}' cy='{}' r='4' fill='{}'><title>{}: {} {}</title></circle>",
                       x(c.measured / reference(c)), y, c.passed() ? "#2a7d2a" : "#c62828",
                       html_escape(c.id), show_value(c.measured), html_escape(c.unit));
  }
  for (double t : {lo, 1.0, hi})
    svg += fmt::format("<text x='{}' y='{}' font-size='11' text-anchor='middle'>{:.3g}</text>",
                       x(t), height - 12, t);
  svg += "</svg>";
  return "<figure>" + svg + "<figcaption>" + html_escape(title) +
         ": the green bar is the pass band, the dot the measured value (green: pass, red: "
         "fail), both over the expected value (where there is none: the band's middle, or its "
         "bound if it is open); checks centred on 0 are in the table only.</figcaption></figure>\n";
}

}  // namespace

std::string terminal_table(const SuiteResult& r) {
  std::string out = text_table(rows(r), false, {false, false, true, true, false});
  for (const Check& c : r.checks)
    if (c.failed())
      out += fmt::format("FAIL {}: measured {} {}, expected {} ({})\n  look at: {}\n", c.id,
                         show_value(c.measured), c.unit, band(c), c.source, c.look_at);
  return out + summary(r) + "\n";
}

namespace {

// Text for Markdown: a '*' or '_' in a name (type.*.nodes_per_ray) is not emphasis.
std::string md(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '*' || c == '_') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

std::string markdown_page(const SuiteResult& r) {
  std::string out = "# rtsim validate: " + r.config_name + "\n\n" + summary(r) + "\n\n";
  out += text_table(rows(r), true, {false, false, true, true, false});
  out += "\n## Checks\n";
  for (const Check& c : r.checks) {
    out += fmt::format("\n### {} ({})\n\n{}\n\n- source: {}\n", md(c.id), status(c), md(c.title),
                       md(c.source));
    if (!c.ran()) {
      out += "- skipped: " + md(c.skipped) + "\n";
      continue;
    }
    out += fmt::format("- measured: {} {}; pass band: {}\n- how: {}\n", show_value(c.measured),
                       c.unit, band(c), md(c.detail));
    if (c.failed()) out += "- look at: " + md(c.look_at) + "\n";
  }
  return out;
}

std::string html_page(const SuiteResult& r) {
  std::string out =
      "<!doctype html><html><head><meta charset='utf-8'><title>rtsim validate: " +
      html_escape(r.config_name) +
      "</title><style>body{font-family:sans-serif;max-width:1100px;margin:2em auto}"
      "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:3px 6px;"
      "font-size:13px;vertical-align:top}td[data-value]{text-align:right}.pass{color:#2a7d2a}"
      ".fail{color:#c62828;font-weight:bold}.skipped,.info{color:#777}</style></head><body>\n";
  out += "<h1>rtsim validate: " + html_escape(r.config_name) + "</h1>\n<p>" +
         html_escape(summary(r)) + "</p>\n";
  nlohmann::ordered_json doc = suite_json(r);
  auto cell = [&doc](size_t index, const char* key) {
    return reports::html_cell(doc, fmt::format("checks.{}.{}", index, key), reports::Style::Real);
  };
  for (const std::string& suite : suites(r)) {
    out += "<h2>Suite " + html_escape(suite) + "</h2>\n" + band_chart(r, suite);
    out +=
        "<table><tr><th>check</th><th>status</th><th>measured</th><th>expected</th>"
        "<th>low</th><th>high</th><th>unit</th><th>what and source</th></tr>\n";
    for (size_t i = 0; i < r.checks.size(); ++i) {
      const Check& c = r.checks[i];
      if (c.suite != suite) continue;
      std::string state = c.status();
      out += "<tr><td id='" + attr(c.id) + "'>" + html_escape(c.id) + "</td><td class='" + state +
             "'>" + state + "</td>" + cell(i, "measured") + cell(i, "expected") + cell(i, "lo") +
             cell(i, "hi") + "<td>" + html_escape(c.unit) + "</td><td>" + html_escape(c.title) +
             "<br><small>" + html_escape(c.source);
      out +=
          c.ran() ? "<br>how: " + html_escape(c.detail) : "<br>skipped: " + html_escape(c.skipped);
      if (c.failed()) out += "<br>look at: " + html_escape(c.look_at);
      out += "</small></td></tr>\n";
    }
    out += "</table>\n";
  }
  return out + "</body></html>\n";
}

std::string junit_xml(const SuiteResult& r) {
  std::string out = fmt::format(
      "<?xml version='1.0' encoding='UTF-8'?>\n<testsuites name='rtsim validate'>\n"
      "<testsuite name='{}' tests='{}' failures='{}' skipped='{}'>\n",
      attr(r.config_name), r.checks.size(), r.failed(), r.skipped());
  for (const Check& c : r.checks) {
    out += fmt::format("<testcase classname='{}' name='{}'>", attr(c.suite), attr(c.id));
    if (!c.ran()) {
      out += "<skipped message='" + attr(c.skipped) + "'/>";
    } else if (c.failed()) {
      out += fmt::format("<failure message='measured {} {}, expected {}'>{}; look at: {}</failure>",
                         show_value(c.measured), attr(c.unit), attr(band(c)), html_escape(c.source),
                         html_escape(c.look_at));
    }
    out += "</testcase>\n";
  }
  return out + "</testsuite>\n</testsuites>\n";
}

}  // namespace rtsim::validation
