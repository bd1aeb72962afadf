#include "reports/page_util.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/core.h>

#include "traces/error.h"
#include "traces/text_table.h"

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
  if (schema && (!doc.is_object() || at_key(doc, "schema") != schema))
    throw_input_error(path, "key schema", std::string("expected ") + schema);
  return doc;
}

namespace {

const char* kind_name(JsonKind kind) {
  switch (kind) {
    case JsonKind::String: return "a string";
    case JsonKind::Bool: return "true or false";
    case JsonKind::Count: return "a whole number >= 0";
    case JsonKind::Number: return "a number";
    case JsonKind::Object: return "an object";
    case JsonKind::Array: return "an array";
    case JsonKind::Present: return "a value";
    case JsonKind::ObjectOrNull: return "an object or null";
  }
  return "";
}

bool is_kind(const Json& v, JsonKind kind) {
  switch (kind) {
    case JsonKind::String: return v.is_string();
    case JsonKind::Bool: return v.is_boolean();
    case JsonKind::Count: return v.is_number_unsigned();
    case JsonKind::Number: return v.is_number();
    case JsonKind::Object: return v.is_object();
    case JsonKind::Array: return v.is_array();
    case JsonKind::Present: return true;
    case JsonKind::ObjectOrNull: return v.is_object() || v.is_null();
  }
  return false;
}

// Checks the field's kind at parts[i...] under node, which is at key `path` of the document.
void require_at(const Json& node, const std::vector<std::string>& parts, size_t i,
                const std::string& path, JsonKind kind, const std::string& file) {
  auto fail = [&](const std::string& key, const char* expected, const Json& v) {
    throw_input_error(file, "key " + key,
                      fmt::format("expected {}, found {}", expected, v.type_name()));
  };
  if (i == parts.size()) {
    if (!is_kind(node, kind)) fail(path, kind_name(kind), node);
    return;
  }
  std::string prefix = path.empty() ? "" : path + ".";
  if (parts[i] == "*") {
    if (!node.is_array() && !node.is_object()) fail(path, "an array or object", node);
    size_t index = 0;
    for (auto it = node.begin(); it != node.end(); ++it, ++index)
      require_at(*it, parts, i + 1, prefix + (node.is_array() ? std::to_string(index) : it.key()),
                 kind, file);
    return;
  }
  if (!node.is_object()) fail(path, "an object", node);
  auto it = node.find(parts[i]);
  if (it == node.end()) {
    const char* expected = i + 1 == parts.size() ? kind_name(kind)
                           : parts[i + 1] == "*" ? "an array or object"
                                                 : "an object";
    throw_input_error(file, "key " + prefix + parts[i],
                      std::string("missing (expected ") + expected + ")");
  }
  require_at(*it, parts, i + 1, prefix + parts[i], kind, file);
}

}  // namespace

void require_fields(const Json& doc, const std::string& file,
                    const std::vector<JsonField>& fields) {
  for (const JsonField& f : fields) {
    std::vector<std::string> parts;
    for (size_t start = 0, end = 0; end != std::string::npos; start = end + 1) {
      end = f.key.find('.', start);
      parts.push_back(f.key.substr(start, end == std::string::npos ? end : end - start));
    }
    require_at(doc, parts, 0, "", f.kind, file);
  }
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
  if (!v.is_number()) return v.dump();  // an object or array where a number belongs
  if (style == Style::Percent) return fmt::format("{:.2f}%", 100 * v.get<double>());
  if (v.is_number_unsigned()) return whole_number(v.get<uint64_t>());
  double x = v.get<double>();
  // Whole from 1,000 on: 11,603 not 1.16e+04.
  if (v.is_number_integer() || style == Style::Integer || (std::isfinite(x) && std::abs(x) >= 1000))
    return whole_number(x);
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
