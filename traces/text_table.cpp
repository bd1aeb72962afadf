#include "traces/text_table.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace rtsim {

std::string whole_number(uint64_t value) {
  std::string digits = std::to_string(value);
  if (digits.size() > 4)
    for (size_t i = digits.size(); i > 3; i -= 3) digits.insert(i - 3, ",");
  return digits;
}

std::string whole_number(double value) {
  if (!std::isfinite(value)) return fmt::format("{}", value);
  double magnitude = std::round(std::abs(value));
  // Past 2^64 a real has no whole digits worth grouping.
  if (magnitude >= 18446744073709551616.0) return fmt::format("{:.4g}", value);
  return (value < 0 && magnitude > 0 ? "-" : "") + whole_number(uint64_t(magnitude));
}

std::string text_table(const std::vector<std::vector<std::string>>& rows, bool markdown,
                       const std::vector<bool>& right_aligned) {
  auto right = [&](size_t column) {
    return column < right_aligned.size() && right_aligned[column];
  };
  std::vector<size_t> width;
  for (const auto& row : rows) {
    width.resize(std::max(width.size(), row.size()), 0);
    for (size_t i = 0; i < row.size(); ++i) width[i] = std::max(width[i], row[i].size());
  }
  std::string out;
  for (size_t n = 0; n < rows.size(); ++n) {
    for (size_t i = 0; i < rows[n].size(); ++i) {
      if (markdown)
        out += "| " + rows[n][i] + " ";
      else
        out += fmt::format(right(i) ? "{:>{}}  " : "{:<{}}  ", rows[n][i], width[i]);
    }
    if (markdown)
      out += "|";
    else
      out.erase(out.find_last_not_of(' ') + 1);
    out += "\n";
    if (markdown && n == 0) {
      for (size_t i = 0; i < rows[n].size(); ++i) out += right(i) ? "|---:" : "|---";
      out += "|\n";
    }
  }
  return out;
}

}  // namespace rtsim
