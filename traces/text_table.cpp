#include "traces/text_table.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace rtsim {

namespace {

std::string grouped(std::string digits) {
  if (digits.size() > 4)
    for (size_t i = digits.size(); i > 3; i -= 3) digits.insert(i - 3, ",");
  return digits;
}

}  // namespace

std::string whole_number(uint64_t value) {
  return grouped(std::to_string(value));
}

std::string whole_number(double value) {
  if (!std::isfinite(value) || std::abs(value) >= 1e21) return fmt::format("{:.4g}", value);
  std::string digits = fmt::format("{:.0f}", std::abs(value));  // rounded as printf rounds
  return (value < 0 && digits != "0" ? "-" : "") + grouped(digits);
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
