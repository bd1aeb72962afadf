// `rtsim regress`: against its own baseline it passes (exit 0, JUnit XML without failures);
// after a config change that slows the design beyond the tolerance it fails (exit 1, the delta
// table and the JUnit XML say which metric); a faster design passes as "improved". At 32x18 some
// ray types have a few rays, whose DRAM bytes move by whole 64-byte lines when more MSHRs
// reorder the misses (which ray fetches a shared line first), hence 4 lines' tolerance. Energy
// per ray is compared too: another process node regresses it and no timing figure.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/reports/report_test_util.h"

namespace rtsim {
namespace {

namespace fs = std::filesystem;

class Regress : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::fresh_dir("regress");
    fs::copy_file(test::source_path("configs/mobile.toml"), dir_ + "/hw.toml");
    std::ofstream(dir_ + "/suite.toml") << "name = \"tiny\"\n"
                                           "config = \"hw.toml\"\n"
                                           "[[case]]\n"
                                           "name = \"pica\"\n"
                                           "workload = \"pica\"\n"
                                           "resolution = \"32x18\"\n"
                                           "[tolerance]\n"
                                           "cycles = 0.02\n"
                                           "l1_hit_rate = { absolute = 0.01 }\n"
                                           "\"type.*.dram_bytes_per_ray\" = "
                                           "{ relative = 0.05, absolute = 256 }\n"
                                           "energy_nj_per_ray = 0.01\n";
    test::RunResult r = regress("--update-baseline");
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  }
  void TearDown() override { fs::remove_all(dir_); }

  test::RunResult regress(const std::string& extra = "") {
    return test::run_rtsim("regress " + dir_ + "/suite.toml --baseline " + dir_ + "/baseline -o " +
                           dir_ + "/out " + extra);
  }
  // Replaces the first `from` of the config (the mobile preset's [rt.l1] comes first).
  void change_config(const std::string& from, const std::string& to) {
    std::string config = test::slurp(dir_ + "/hw.toml");
    size_t at = config.find(from);
    ASSERT_NE(at, std::string::npos) << "the mobile preset has " << from;
    config.replace(at, from.size(), to);
    std::ofstream(dir_ + "/hw.toml") << config;
  }
  std::string dir_;
};

TEST_F(Regress, PassesAgainstItsOwnBaseline) {
  EXPECT_TRUE(fs::exists(dir_ + "/baseline/baseline.json"));
  test::RunResult r = regress();
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("cycles"), std::string::npos) << "the delta table names each metric";
  std::string junit = test::slurp(dir_ + "/out/junit.xml");
  EXPECT_NE(junit.find("<testsuite name=\"rtsim.regress.tiny\""), std::string::npos) << junit;
  EXPECT_NE(junit.find("failures=\"0\""), std::string::npos) << junit;
  EXPECT_EQ(junit.find("<failure"), std::string::npos) << junit;
}

TEST_F(Regress, FailsWhenAConfigChangeSlowsTheDesign) {
  change_config("mshrs = 16", "mshrs = 2");  // the L1's
  test::RunResult r = regress();
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("regressed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("FAILED"), std::string::npos) << r.out;
  std::string junit = test::slurp(dir_ + "/out/junit.xml");
  EXPECT_NE(junit.find("name=\"cycles\" time=\"0\"><failure"), std::string::npos) << junit;
  EXPECT_NE(test::slurp(dir_ + "/out/deltas.md").find("regressed"), std::string::npos);
}

TEST_F(Regress, AFasterDesignPassesAsImproved) {
  change_config("mshrs = 16", "mshrs = 64");  // the L1's
  test::RunResult r = regress();
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("improved"), std::string::npos) << r.out;
}

TEST_F(Regress, AnOlderProcessNodeRegressesEnergyNotCycles) {
  std::ofstream(dir_ + "/hw.toml", std::ios::app) << "\n[energy]\nnode = \"45nm\"\n";
  test::RunResult r = regress();
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  std::string junit = test::slurp(dir_ + "/out/junit.xml");
  EXPECT_NE(junit.find("name=\"energy_nj_per_ray\" time=\"0\"><failure"), std::string::npos)
      << junit;
  EXPECT_EQ(junit.find("name=\"cycles\" time=\"0\"><failure"), std::string::npos)
      << "the energy model changes no timing";
}

TEST_F(Regress, AMissingBaselineIsBadInput) {
  test::RunResult r = test::run_rtsim("regress " + dir_ + "/suite.toml --baseline " + dir_ +
                                      "/nothing -o " + dir_ + "/out");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--update-baseline"), std::string::npos) << r.err;
}

TEST(RegressCli, AMisspeltMetricIsBadInputBeforeAnyCaseRuns) {
  std::string dir = test::fresh_dir("regress-metric");
  std::ofstream(dir + "/suite.toml") << "[[case]]\nname = \"pica\"\nworkload = \"pica\"\n"
                                        "[tolerance]\ncycels = 0.01\n";
  test::RunResult r =
      test::run_rtsim("regress " + dir + "/suite.toml --baseline " + dir + "/b -o " + dir + "/out");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_EQ(r.err.rfind("rtsim: error: " + dir +
                            "/suite.toml: line 5: [tolerance] unknown metric "
                            "'cycels'",
                        0),
            0u)
      << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out/cases")) << "no case ran";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rtsim
