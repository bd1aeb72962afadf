// Helpers for the report pages: escaping, base64 for embedded images, and number cells that
// carry the JSON key and raw value they show (data-key, data-value), so a page can be checked
// against its JSON (tests/reports) and a reader can find where a number comes from.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace rtsim::reports {

enum class Style { Integer, Real, Percent, Text };

std::string html_escape(const std::string& text);
std::string base64(const std::string& bytes);
std::string read_file(const std::string& path);  // "" if missing
// A JSON document rtsim wrote. Throws InputError naming the file if it is missing, not valid
// JSON (with the byte where parsing stopped) or its "schema" is not the one expected (when
// schema is not null).
nlohmann::ordered_json read_json_file(const std::string& path, const char* schema);

// What a document read back must hold at a key for the code that reads it: a value of a kind.
enum class JsonKind { String, Bool, Count, Number, Object, Array, Present, ObjectOrNull };
struct JsonField {
  std::string key;  // dotted, as at_key reads it; a part "*" stands for every element or value
  JsonKind kind;
};

// Checks that doc, read from file, holds every field, so that code reading it needs no checks
// of its own. Throws InputError "FILE: key K: WHAT" naming the first key missing or of another
// kind.
void require_fields(const nlohmann::ordered_json& doc, const std::string& file,
                    const std::vector<JsonField>& fields);

// The value at a dotted key ("timing.cycles", "workload.passes.0.rays": a number indexes an
// array); null if any part is missing.
const nlohmann::ordered_json& at_key(const nlohmann::ordered_json& doc, const std::string& key);

// The value of a swept key in a point's "values" (keyed by the whole dotted name); null if
// the point does not set it.
const nlohmann::ordered_json& swept_value(const nlohmann::ordered_json& values,
                                          const std::string& key);

// How a value is shown: integers, and reals from 1,000 on, whole with the one thousands rule
// (whole_number, traces/text_table.h: 9999, 10,000); smaller reals to 4 significant digits;
// rates (fractions in the JSON) as percentages with 2 decimals; null as "n/a".
std::string show(const nlohmann::ordered_json& value, Style style);

// <td data-key=KEY data-value=RAW>SHOWN</td> for the value at key in doc.
std::string html_cell(const nlohmann::ordered_json& doc, const std::string& key, Style style);

// A two-column table: label, value (rows of label, key, style).
struct Row {
  std::string label, key;
  Style style;
  bool brief = true;         // also in the Markdown pages (markdown_rows skips the others)
  bool exact_hides = false;  // left out where the value is 0 or null (an interval of an exact run)
};
std::string html_rows(const nlohmann::ordered_json& doc, const std::vector<Row>& rows);

std::string markdown_rows(const nlohmann::ordered_json& doc, const std::vector<Row>& rows);

}  // namespace rtsim::reports
