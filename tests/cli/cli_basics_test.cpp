// The command line's contract: help, version, and exit code 2 for usage errors.
#include <gtest/gtest.h>

#include "run_rtsim.h"

namespace rtsim::test {
namespace {

TEST(Cli, HelpListsTheSubcommands) {
  RunResult r = run_rtsim("--help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* cmd : {"scene-info", "trace-info"})
    EXPECT_NE(r.out.find(cmd), std::string::npos) << cmd << " missing from --help:\n" << r.out;
}

TEST(Cli, EverySubcommandHasHelp) {
  for (const char* cmd : {"scene-info", "trace-info"}) {
    RunResult r = run_rtsim(std::string(cmd) + " --help");
    EXPECT_EQ(r.exit_code, 0) << cmd;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << cmd;
  }
}

TEST(Cli, VersionPrintsTheVersion) {
  RunResult r = run_rtsim("--version");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("rtsim "), std::string::npos);
}

TEST(Cli, UsageErrorsExitWith2) {
  EXPECT_EQ(run_rtsim("").exit_code, 2);
  EXPECT_EQ(run_rtsim("no-such-command").exit_code, 2);
  EXPECT_EQ(run_rtsim("scene-info").exit_code, 2);
  EXPECT_EQ(run_rtsim("scene-info cornell --no-such-flag").exit_code, 2);
}

TEST(CliUsage, UsageErrorsAreOneLineWithTheCommandAndExitTwo) {
  struct Case {
    const char* args;
    const char* first_line;
  };
  for (const Case& c : {
           Case{"", "rtsim: error: a command is required (scene-info, "},
           Case{"bogus", "rtsim: error: unknown command 'bogus' (commands: scene-info, "},
           Case{"trace cornell --seed -1 -o x.rays",
                "rtsim: error: trace: --seed: '-1' must not be negative"},
           Case{"run pica --seed -1 -o x", "rtsim: error: run: --seed: '-1' must not be negative"},
           Case{"trace cornell --frames 0 -o x.rays",
                "rtsim: error: trace: --frames: Value 0 not in range 1 to 100000"},
           Case{"sim --bogus",
                "rtsim: error: sim: The following argument was not expected: --bogus"},
       }) {
    RunResult r = run_rtsim(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args;
    EXPECT_EQ(r.err.rfind(c.first_line, 0), 0u) << c.args << ": " << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << c.args << ": " << r.err;
  }
}

}  // namespace
}  // namespace rtsim::test
