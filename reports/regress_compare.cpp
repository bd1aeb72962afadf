#include "reports/regress_compare.h"

#include <cmath>

#include <fmt/core.h>

#include "reports/metrics.h"
#include "reports/page_util.h"
#include "traces/text_table.h"

namespace rtsim::reports {
using Json = nlohmann::ordered_json;

namespace {

// A metric of a flat map (names hold dots: "type.camera.latency_p50").
Json flat_value(const Json& metrics, const std::string& name) {
  return metrics.is_object() && metrics.contains(name) ? metrics[name] : Json();
}

// The metric names a tolerance covers for one case ("type.*.X": X of every ray type).
std::vector<std::string> covered(const Tolerance& t, const Json& a, const Json& b) {
  if (t.metric.rfind("type.*.", 0) != 0) return {t.metric};
  std::string suffix = "." + t.metric.substr(7);
  std::vector<std::string> out;
  for (const Json* m : {&a, &b})
    if (m->is_object())
      for (const auto& [name, value] : m->items())
        if (name.rfind("type.", 0) == 0 && name.size() > suffix.size() &&
            name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0 &&
            std::find(out.begin(), out.end(), name) == out.end())
          out.push_back(name);
  return out;
}

MetricCheck check(const std::string& name, const Tolerance& t, const std::string& metric,
                  const Json& base, const Json& now) {
  MetricCheck c{name, metric, t.direction.empty() ? metric_direction(metric) : t.direction,
                base, now,    0,
                "ok"};
  if (base.is_null() || now.is_null() || !base.is_number() || !now.is_number()) {
    c.status = base.is_null() && now.is_null() ? "ok" : "missing";
    return c;
  }
  double b = base.get<double>(), n = now.get<double>();
  c.allowed = std::max(t.relative * std::abs(b), t.absolute);
  double delta = n - b;
  if (std::abs(delta) <= c.allowed) return c;
  bool worse = c.direction == "lower" ? delta > 0 : c.direction == "higher" ? delta < 0 : true;
  c.status = c.direction == "either" ? "changed" : worse ? "regressed" : "improved";
  return c;
}

}  // namespace

bool RegressResult::failed() const {
  if (!case_failures.empty()) return true;
  for (const MetricCheck& c : checks)
    if (c.failed()) return true;
  return false;
}

Json baseline_json(const RegressSuite& suite, const std::vector<CaseOutcome>& cases) {
  Json out = {
      {"schema", kBaselineSchema}, {"suite", suite.name}, {"generator", "rtsim " RTSIM_VERSION}};
  Json all = Json::object();
  for (const CaseOutcome& c : cases) all[c.name] = {{"metrics", c.metrics}};
  out["cases"] = all;
  return out;
}

RegressResult compare_with_baseline(const RegressSuite& suite, std::vector<CaseOutcome> cases,
                                    const Json& baseline) {
  RegressResult r;
  r.cases = std::move(cases);
  for (const CaseOutcome& c : r.cases) {
    if (!c.ran) {
      r.case_failures.push_back(fmt::format("{}: the run failed (exit {})", c.name, c.exit_code));
      continue;
    }
    const Json& u = at_key(c.metrics, "unexplained");
    if (suite.verify && u.is_null())
      r.case_failures.push_back(c.name + ": not verified (the suite needs the cycle level)");
    else if (suite.verify && u.get<uint64_t>() > 0)
      r.case_failures.push_back(fmt::format("{}: verification failed: {} unexplained mismatches",
                                            c.name, u.get<uint64_t>()));
    if (!baseline["cases"].contains(c.name)) {
      r.case_failures.push_back(c.name + ": not in the baseline (record one: --update-baseline)");
      continue;
    }
    const Json& base = baseline["cases"][c.name]["metrics"];
    for (const Tolerance& t : suite.tolerances)
      for (const std::string& m : covered(t, base, c.metrics))
        r.checks.push_back(check(c.name, t, m, flat_value(base, m), flat_value(c.metrics, m)));
  }
  return r;
}

std::string delta_table(const RegressResult& r, bool markdown) {
  std::vector<std::vector<std::string>> rows{
      {"case", "metric", "baseline", "now", "delta", "allowed", "status"}};
  for (const MetricCheck& c : r.checks) {
    std::string delta = "-";
    if (c.baseline.is_number() && c.current.is_number()) {
      double b = c.baseline.get<double>(), n = c.current.get<double>();
      delta = b != 0 ? fmt::format("{:+.2f}%", 100 * (n / b - 1)) : fmt::format("{:+.4g}", n - b);
    }
    rows.push_back({c.case_name, c.metric, show(c.baseline, Style::Real),
                    show(c.current, Style::Real), delta, fmt::format("±{:.4g}", c.allowed),
                    c.status});
  }
  std::string out = text_table(rows, markdown);
  for (const std::string& f : r.case_failures)
    out += (markdown ? "\n- **FAILED** " : "FAILED  ") + f + "\n";
  return out;
}

std::string junit_xml(const RegressSuite& suite, const RegressResult& r) {
  size_t tests = r.checks.size() + r.cases.size(), failures = 0;
  for (const MetricCheck& c : r.checks) failures += c.failed();
  std::string body;
  for (const CaseOutcome& c : r.cases) {
    std::string failure;
    for (const std::string& f : r.case_failures)
      if (f.rfind(c.name + ":", 0) == 0) failure += f + "\n";
    failures += !failure.empty();
    body += fmt::format(
        "    <testcase classname=\"{}.{}\" name=\"run and verification\" time=\"{:.3f}\">",
        html_escape(suite.name), html_escape(c.name), c.seconds);
    if (!failure.empty())
      body += fmt::format("<failure message=\"{}\">{}</failure>",
                          html_escape(failure.substr(0, failure.find('\n'))), html_escape(failure));
    body += "</testcase>\n";
  }
  for (const MetricCheck& c : r.checks) {
    body += fmt::format("    <testcase classname=\"{}.{}\" name=\"{}\" time=\"0\">",
                        html_escape(suite.name), html_escape(c.case_name), html_escape(c.metric));
    std::string detail =
        fmt::format("{}: baseline {}, now {}, allowed deviation {:.6g} ({} is better)", c.status,
                    c.baseline.dump(), c.current.dump(), c.allowed,
                    c.direction == "higher"  ? "higher"
                    : c.direction == "lower" ? "lower"
                                             : "neither");
    if (c.failed())
      body += fmt::format("<failure message=\"{}\">{}</failure>", html_escape(detail),
                          html_escape(detail));
    else if (c.status == "improved")
      body += "<system-out>" + html_escape(detail + "; update the baseline") + "</system-out>";
    body += "</testcase>\n";
  }
  return fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites tests=\"{}\" "
      "failures=\"{}\">\n  <testsuite name=\"rtsim.regress.{}\" tests=\"{}\" "
      "failures=\"{}\" errors=\"0\" skipped=\"0\">\n{}  </testsuite>\n</testsuites>\n",
      tests, failures, html_escape(suite.name), tests, failures, body);
}

Json regress_json(const RegressSuite& suite, const RegressResult& r) {
  Json checks = Json::array();
  for (const MetricCheck& c : r.checks)
    checks.push_back({{"case", c.case_name},
                      {"metric", c.metric},
                      {"baseline", c.baseline},
                      {"current", c.current},
                      {"allowed", c.allowed},
                      {"direction", c.direction},
                      {"status", c.status}});
  return {{"schema", "rtsim.regress/1"},
          {"suite", suite.name},
          {"failed", r.failed()},
          {"case_failures", r.case_failures},
          {"checks", checks}};
}

}  // namespace rtsim::reports
