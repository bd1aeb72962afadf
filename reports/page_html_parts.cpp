// Shared parts of the HTML pages: chrome, per-type tables and the image gallery.
#include <algorithm>

#include <fmt/core.h>

#include "reports/page_util.h"
#include "reports/report_pages.h"

namespace rtsim::reports {

using Json = nlohmann::ordered_json;

std::string html_head(const std::string& title) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
         html_escape(title) +
         "</title>\n<style>\n"
         "body{font-family:system-ui,sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;"
         "color:#222}\n"
         "h1{font-size:1.6em}h2{border-bottom:1px solid "
         "#ccc;padding-bottom:.2em;margin-top:1.6em}\n"
         "table{border-collapse:collapse;margin:.6em 0}td,th{border:1px solid #ddd;"
         "padding:.25em .6em;text-align:right}th{background:#f4f4f4;text-align:left}\n"
         "td.na{color:#999}.meta{color:#666;font-size:.9em}nav a{margin-right:1em}\n"
         "figure{margin:1em 0}figure img{max-width:100%;border:1px solid #eee}\n"
         "figcaption{font-size:.9em;color:#444}.missing{color:#a00}\n"
         ".pass{color:#070;font-weight:bold}.fail{color:#b00;font-weight:bold}\n"
         "pre{background:#f8f8f8;padding:.6em;overflow:auto;font-size:.85em}\n"
         "</style>\n</head>\n<body>\n";
}

std::string html_tail() {
  return "</body>\n</html>\n";
}

std::string html_type_table(const Json& doc, const std::string& prefix,
                            const std::vector<Column>& columns, const std::string& row_title) {
  const Json& rows = at_key(doc, prefix);
  if (!rows.is_object() || rows.empty()) return "<p class=\"na\">n/a</p>\n";
  std::string out = "<table>\n<tr><th>" + html_escape(row_title) + "</th>";
  for (const Column& c : columns) out += "<th>" + html_escape(c.title) + "</th>";
  out += "</tr>\n";
  for (const auto& [name, row] : rows.items()) {
    out += "<tr><th>" + html_escape(name) + "</th>";
    for (const Column& c : columns)
      out +=
          html_cell(doc, prefix + "." + name + (c.key.empty() ? "" : "." + c.key), Style(c.style));
    out += "</tr>\n";
  }
  return out + "</table>\n";
}

std::string markdown_type_table(const Json& doc, const std::string& prefix,
                                const std::vector<Column>& columns, const std::string& row_title) {
  const Json& rows = at_key(doc, prefix);
  if (!rows.is_object() || rows.empty()) return "n/a\n";
  std::string out = "| " + row_title + " |";
  for (const Column& c : columns) out += " " + c.title + " |";
  out += "\n|---|";
  for (size_t i = 0; i < columns.size(); ++i) out += "---|";
  out += "\n";
  for (const auto& [name, row] : rows.items()) {
    out += "| " + name + " |";
    for (const Column& c : columns)
      out += " " + show(c.key.empty() ? row : at_key(row, c.key), Style(c.style)) + " |";
    out += "\n";
  }
  return out;
}

std::string html_figures(const Json& report, const std::string& run_dir,
                         const std::vector<std::string>& kinds) {
  std::string out;
  for (const Json& image : report["images"]) {
    std::string kind = image["kind"].get<std::string>();
    if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end()) continue;
    std::string id = image["id"].get<std::string>(), file = image["file"].get<std::string>();
    std::string title = html_escape(image["title"].get<std::string>());
    std::string caption =
        fmt::format("<figcaption><b>{}</b> ({}): {}</figcaption>", title, html_escape(file),
                    html_escape(image["caption"].get<std::string>()));
    std::string png = image["available"].get<bool>() ? read_file(run_dir + "/" + file) : "";
    if (png.empty()) {
      std::string reason = image["reason"].get<std::string>();
      out += fmt::format(
          "<figure id=\"img-{}\" data-image=\"{}\" class=\"missing\"><p>{}: not "
          "available ({})</p>{}</figure>\n",
          id, id, title, html_escape(reason.empty() ? "file missing" : reason), caption);
      continue;
    }
    out += fmt::format(
        "<figure id=\"img-{}\" data-image=\"{}\"><img alt=\"{}\" "
        "src=\"data:image/png;base64,{}\">{}</figure>\n",
        id, id, title, base64(png), caption);
  }
  return out;
}

}  // namespace rtsim::reports
