// text_table: terminal columns padded to the widest cell (numbers on the right), no trailing
// blanks; Markdown with a rule under the header that right-aligns the number columns.
#include "traces/text_table.h"

#include <gtest/gtest.h>

namespace rtsim {
namespace {

const std::vector<std::vector<std::string>> kRows{
    {"strategy", "dev", "note"}, {"balanced", "2.51%", "ok"}, {"cost", "12.85%", ""}};

TEST(TextTable, TerminalPadsColumnsAndAlignsNumbersRight) {
  EXPECT_EQ(text_table(kRows, false, {false, true}),
            "strategy     dev  note\n"
            "balanced   2.51%  ok\n"
            "cost      12.85%\n");
  EXPECT_EQ(text_table(kRows, false),
            "strategy  dev     note\n"
            "balanced  2.51%   ok\n"
            "cost      12.85%\n");
}

TEST(TextTable, MarkdownRulesNumberColumnsRight) {
  EXPECT_EQ(text_table(kRows, true, {false, true}),
            "| strategy | dev | note |\n"
            "|---|---:|---|\n"
            "| balanced | 2.51% | ok |\n"
            "| cost | 12.85% |  |\n");
}

}  // namespace
}  // namespace rtsim
