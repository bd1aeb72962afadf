// The pages of a run report, rendered from its JSON (report_doc.h): report.html, one
// self-contained page (styles inline, images embedded as data: URIs, so it opens offline from
// disk and can be mailed as one file), and report.md, a Markdown summary that links the PNGs
// under images/. Every number cell of the HTML names its JSON key (data-key) and raw value.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "reports/page_util.h"

namespace rtsim::reports {

// run_dir: where images/ are read from (for embedding).
std::string report_html(const nlohmann::ordered_json& report, const std::string& run_dir);
std::string report_markdown(const nlohmann::ordered_json& report);

// What the workload section says of a run that read a ray stream, not a trace folder.
constexpr const char* kNoPasses =
    "Passes not recorded: the run read a ray stream, whose header holds the workload, scene, "
    "grid, frames and rays per type, not the passes that made them.";

// The labelled values of the summary, workload, hardware, timing, bandwidth and DRAM sections, for
// both pages (report_rows.cpp).
const std::vector<Row>& summary_rows();
const std::vector<Row>& workload_rows();
const std::vector<Row>& hardware_rows();
// Two BVH levels (coherence.instances_per_ray not null): transforms, and each level's figures.
const std::vector<Row>& two_level_rows();
const std::vector<Row>& timing_rows();
const std::vector<Row>& bandwidth_rows();
const std::vector<Row>& dram_rows();
// Energy and area (null below cycle level), and the per-structure table's columns.
const std::vector<Row>& energy_rows();

// A table with one row per key of doc[prefix] (ray types, or what row_title names), columns
// (title, key under the row, style); the HTML cells carry their full keys.
struct Column {
  std::string title, key;
  int style;  // a Style
};
std::string html_type_table(const nlohmann::ordered_json& doc, const std::string& prefix,
                            const std::vector<Column>& columns,
                            const std::string& row_title = "ray type");
std::string markdown_type_table(const nlohmann::ordered_json& doc, const std::string& prefix,
                                const std::vector<Column>& columns,
                                const std::string& row_title = "ray type");
const std::vector<Column>& energy_structure_columns();

// The image gallery of one kind list ("picture,heatmap" or "chart").
std::string html_figures(const nlohmann::ordered_json& report, const std::string& run_dir,
                         const std::vector<std::string>& kinds);

// Shared page chrome: head with the inline style sheet, and the end.
std::string html_head(const std::string& title);
std::string html_tail();

}  // namespace rtsim::reports
