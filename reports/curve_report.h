// What `rtsim curve` writes (model/fidelity/CURVE.md): the curve as JSON (schema rtsim.curve/1),
// CSV, a terminal or Markdown table, from the pass's CacheCurve; the chart is
// reports/charts/curve_chart.py over the JSON.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/fidelity/cache_curve.h"

namespace rtsim::reports {

// "32 KiB", "4 MiB", "100 B"; compact: "32K", "4M", "100", as the command's options take them.
std::string size_text(uint64_t bytes, bool compact = false);
// context: what was run (stream, scene, config, ...), copied into the document.
nlohmann::ordered_json curve_json(const CacheCurve& curve, const nlohmann::ordered_json& context);
std::string curve_table(const nlohmann::ordered_json& doc, bool markdown);
std::string curve_csv(const nlohmann::ordered_json& doc);
std::string curve_markdown(const nlohmann::ordered_json& doc);
// The curves of several L1 sizes (`rtsim curve --l1`, one document each): one table of their
// first associativity's points, L1 by L1, and the chart curve-l1.png.
std::string curve_family_markdown(const std::vector<nlohmann::ordered_json>& docs);

}  // namespace rtsim::reports
