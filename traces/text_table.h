// A table as text, for the terminal (columns padded to their widest cell, two spaces apart) or
// in Markdown. The first row is the header. Columns marked in right_aligned (numbers) are
// padded on the left on the terminal and ruled "---:" in Markdown; the others align left.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rtsim {

// A whole number as every table and summary writes one (terminal, Markdown, HTML): digits
// grouped by commas from 10,000 up (9999, 10,000, 1,234,567); a real is rounded first.
std::string whole_number(uint64_t value);
std::string whole_number(double value);

std::string text_table(const std::vector<std::vector<std::string>>& rows, bool markdown,
                       const std::vector<bool>& right_aligned = {});

}  // namespace rtsim
