// `rtsim report` on a report.json or sweep.json that is not as rtsim wrote it (issue 63): with
// any one key removed, or its value of another kind, rewriting the pages either works or throws
// InputError naming the file and the key; never another exception.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "reports/report_writer.h"
#include "reports/sweep_report.h"
#include "reports/sweep_spec.h"
#include "tests/reports/report_test_util.h"
#include "traces/error.h"

namespace rtsim {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// The keys of doc as JSON pointers ("/workload/passes/0/rays"), to three object levels deep
// (where the pages' direct reads are; below, whole sections are read as values or through
// at_key), and of an array the first element's only (its elements are alike): about 300 keys
// of a run's report, so that the test takes seconds.
void pointers(const Json& doc, const std::string& at, int depth, std::vector<std::string>& out) {
  if ((!doc.is_object() && !doc.is_array()) || depth == 3) return;
  if (doc.is_array() && !doc.empty()) {
    out.push_back(at + "/0");
    pointers(doc[0], at + "/0", depth, out);
    return;
  }
  for (const auto& [name, value] : doc.items()) {
    std::string key = name;
    for (auto [from, to] : {std::pair{"~", "~0"}, std::pair{"/", "~1"}})
      for (size_t i = key.find(from); i != std::string::npos; i = key.find(from, i + 2))
        key.replace(i, 1, to);
    out.push_back(at + "/" + key);
    pointers(value, at + "/" + key, depth + 1, out);
  }
}

// A value of another kind than v.
Json other_kind(const Json& v) {
  return v.is_string() ? Json(7) : Json("x");
}

// Writes each damaged copy of doc to dir/name and runs rewrite on dir: it must work or throw an
// InputError that names the file and (as "key K") the damaged key or one the pages need first.
// Returns how many copies were refused.
size_t damage_each_key(const Json& doc, const std::string& dir, const std::string& name,
                       const std::function<void()>& rewrite) {
  std::vector<std::string> keys;
  pointers(doc, "", 0, keys);
  size_t refused = 0;
  for (const std::string& key : keys)
    for (bool remove : {true, false}) {
      Json copy = doc;
      Json::json_pointer pointer(key);
      Json& parent = copy[pointer.parent_pointer()];
      if (!remove)
        copy[pointer] = other_kind(copy[pointer]);
      else if (parent.is_array())
        parent.erase(size_t(std::stoul(pointer.back())));
      else
        parent.erase(pointer.back());
      std::string path = dir + "/" + name;
      std::ofstream(path) << copy.dump();
      try {
        rewrite();
      } catch (const InputError& e) {
        std::string what = e.what();
        EXPECT_EQ(what.rfind(path + ": key ", 0), 0u) << key << ": " << what;
        ++refused;
      } catch (const std::exception& e) {
        ADD_FAILURE() << (remove ? "removing " : "retyping ") << key << ": " << e.what();
      }
    }
  return refused;
}

TEST(HostileDocuments, ARunReportWithAnyKeyDamagedIsRewrittenOrRefusedNamingTheKey) {
  std::string run = test::shared_run(
      "run", "run pica --resolution 64x36 --config " + test::source_path("configs/mobile.toml"));
  ASSERT_FALSE(run.empty()) << "rtsim run failed";
  Json report = test::read_json(run + "/report.json");
  std::string dir = test::fresh_dir("damaged-run");
  size_t refused = damage_each_key(report, dir, "report.json", [&] {
    reports::rewrite_report(dir, {false, true});
  });
  EXPECT_GT(refused, 20u) << "the keys the pages read are checked";
}

TEST(HostileDocuments, ASweepDocumentWithAnyKeyDamagedIsRewrittenOrRefusedNamingTheKey) {
  reports::SweepSpec spec =
      reports::read_sweep_spec(test::source_path("tests/reports/sweep-tiny.toml"));
  std::vector<reports::PointRun> points;
  for (size_t i = 0; i < spec.points.size(); ++i) {
    reports::PointRun p;
    p.id = "pica-" + std::to_string(i);
    p.workload = "pica";
    p.point = &spec.points[i];
    p.ok = i > 0;  // one failed point: its metrics are null
    p.ran_on = "local on host";
    p.metrics = {{"cycles", 1000 + i},
                 {"energy_nj_per_ray", 2.0 + double(i)},
                 {"sram_area_mm2", 0.01 * double(i)},
                 {"on_chip_bytes", 4096 * i}};
    points.push_back(p);
  }
  Json doc = reports::sweep_json(spec, points);
  ASSERT_FALSE(doc["objective"]["best"][0]["id"].is_null()) << "the objective picks a point";
  std::string dir = test::fresh_dir("damaged-sweep");
  size_t refused = damage_each_key(doc, dir, "sweep.json", [&] {
    reports::rewrite_sweep_report(dir, {false, true});
  });
  EXPECT_GT(refused, 20u) << "the keys the pages read are checked";
}

}  // namespace
}  // namespace rtsim
