// A table as text, for the terminal (columns padded to their widest cell, two spaces apart) or
// in Markdown. The first row is the header. Columns marked in right_aligned (numbers) are
// padded on the left on the terminal and ruled "---:" in Markdown; the others align left.
#pragma once

#include <string>
#include <vector>

namespace rtsim {

std::string text_table(const std::vector<std::vector<std::string>>& rows, bool markdown,
                       const std::vector<bool>& right_aligned = {});

}  // namespace rtsim
