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

}  // namespace
}  // namespace rtsim::test
