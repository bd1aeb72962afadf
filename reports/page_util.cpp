#include "reports/page_util.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/core.h>

#include "traces/error.h"

namespace rtsim::reports {

using Json = nlohmann::ordered_json;

std::string html_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    uint32_t v = uint32_t(uint8_t(bytes[i])) << 16 | uint32_t(uint8_t(bytes[i + 1])) << 8 |
                 uint8_t(bytes[i + 2]);
    for (int s = 18; s >= 0; s -= 6) out += table[(v >> s) & 63];
  }
  if (i < bytes.size()) {
    uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
    if (i + 1 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 1])) << 8;
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

Json read_json_file(const std::string& path, const char* schema) {
  if (!std::ifstream(path)) throw_input_error(path, "", "missing");
  Json doc;
  try {
    doc = Json::parse(read_file(path));
  } catch (const nlohmann::json::parse_error& e) {
    throw_input_error(path, fmt::format("byte {}", e.byte), "not valid JSON");
  }
  if (schema && doc.value("schema", "") != schema)
    throw_input_error(path, "schema", std::string("expected ") + schema);
  return doc;
}

const Json& swept_value(const Json& values, const std::string& key) {
  static const Json null;
  auto it = values.find(key);
  return it == values.end() ? null : *it;
}

const Json& at_key(const Json& doc, const std::string& key) {
  static const Json null;
  const Json* node = &doc;
  size_t start = 0;
  while (start <= key.size()) {
    size_t end = key.find('.', start);
    if (end == std::string::npos) end = key.size();
    std::string part = key.substr(start, end - start);
    if (node->is_array()) {
      size_t index = part.find_first_not_of("0123456789") == std::string::npos && !part.empty()
                         ? std::stoul(part)
                         : node->size();
      if (index >= node->size()) return null;
      node = &(*node)[index];
    } else {
      if (!node->is_object() || !node->contains(part)) return null;
      node = &(*node)[part];
    }
    start = end + 1;
  }
  return *node;
}

std::string show(const Json& v, Style style) {
  if (v.is_null()) return "n/a";
  if (style == Style::Text || v.is_string()) return v.is_string() ? v.get<std::string>() : v.dump();
  if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
  if (style == Style::Percent) return fmt::format("{:.2f}%", 100 * v.get<double>());
  if (v.is_number_integer() || v.is_number_unsigned()) return v.dump();
  if (style == Style::Integer) return fmt::format("{:.0f}", v.get<double>());
  double x = v.get<double>();
  if (std::isfinite(x) && std::abs(x) >= 1000) {  // plain, in thousands: 11,603 not 1.16e+04
    std::string digits = fmt::format("{:.0f}", std::abs(x));
    for (size_t i = digits.size(); i > 3; i -= 3) digits.insert(i - 3, ",");
    return (x < 0 ? "-" : "") + digits;
  }
  return fmt::format("{:.4g}", x);
}

std::string html_cell(const Json& doc, const std::string& key, Style style) {
  const Json& v = at_key(doc, key);
  return fmt::format("<td data-key=\"{}\" data-value=\"{}\"{}>{}</td>", html_escape(key),
                     html_escape(v.dump()), v.is_null() ? " class=\"na\"" : "",
                     html_escape(show(v, style)));
}

namespace {

bool hidden(const Json& doc, const Row& r) {
  if (!r.exact_hides) return false;
  const Json& v = at_key(doc, r.key);
  return v.is_null() || (v.is_number() && v.get<double>() == 0);
}

}  // namespace

std::string html_rows(const Json& doc, const std::vector<Row>& rows) {
  std::string out = "<table class=\"kv\">\n";
  for (const Row& r : rows)
    if (!hidden(doc, r))
      out +=
          "<tr><th>" + html_escape(r.label) + "</th>" + html_cell(doc, r.key, r.style) + "</tr>\n";
  return out + "</table>\n";
}

std::string markdown_rows(const Json& doc, const std::vector<Row>& rows) {
  std::string out = "| | |\n|---|---|\n";
  for (const Row& r : rows)
    if (r.brief && !hidden(doc, r))
      out += "| " + r.label + " | " + show(at_key(doc, r.key), r.style) + " |\n";
  return out;
}

}  // namespace rtsim::reports
