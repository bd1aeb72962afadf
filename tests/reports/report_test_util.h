// Helpers of the reports tests: a fresh temporary folder, files, JSON, and the parts of a
// report page (number cells with their keys, figures with their embedded images).
#pragma once

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "reports/page_util.h"
#include "tests/cli/run_rtsim.h"
#include "tests/temp_dir.h"

namespace rtsim::test {

inline std::string fresh_dir(const std::string& name) {
  std::string dir = scratch_path(name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline nlohmann::ordered_json read_json(const std::string& path) {
  return nlohmann::ordered_json::parse(slurp(path));
}

// Runs `rtsim ARGS -o DIR` once per build of rtsim for all the tests, whichever test process
// comes first (ctest runs each test in its own process, maybe in parallel); the others wait on a
// lock and reuse DIR, which lives in the build folder. Returns DIR, or "" if the run failed.
inline std::string shared_run(const std::string& name, const std::string& args) {
  std::string exe = RTSIM_EXE;
  std::string stamp =
      std::to_string(std::filesystem::last_write_time(exe).time_since_epoch().count());
  std::filesystem::path base = std::filesystem::path(exe).parent_path().parent_path() /
                               "test-runs" / std::to_string(std::hash<std::string>()(args));
  std::filesystem::create_directories(base);
  int lock = open((base / "lock").c_str(), O_CREAT | O_RDWR, 0644);
  flock(lock, LOCK_EX);
  std::string dir = (base / name).string();
  std::string done = dir + "/done";
  if (!std::filesystem::exists(done) || slurp(done) != stamp) {
    std::filesystem::remove_all(dir);
    RunResult r = run_rtsim(args + " -o " + dir);
    if (r.exit_code == 0) std::ofstream(done) << stamp;
  }
  bool ok = std::filesystem::exists(done) && slurp(done) == stamp;
  flock(lock, LOCK_UN);
  close(lock);
  return ok ? dir : "";
}

inline std::string source_path(const std::string& relative) {
  return std::string(RTSIM_SOURCE_DIR) + "/" + relative;
}

struct Cell {
  std::string key, value, shown;
};

// Every <td data-key=... data-value=...>shown</td> of a page, HTML entities undone.
inline std::vector<Cell> number_cells(const std::string& html) {
  auto unescape = [](std::string s) {
    for (auto [from, to] : {std::pair<std::string, std::string>{"&quot;", "\""},
                            {"&lt;", "<"},
                            {"&gt;", ">"},
                            {"&amp;", "&"}}) {
      for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
        s.replace(at, from.size(), to);
    }
    return s;
  };
  std::vector<Cell> out;
  const std::string open = "<td data-key=\"";
  for (size_t at = html.find(open); at != std::string::npos; at = html.find(open, at + 1)) {
    size_t key_end = html.find('"', at + open.size());
    size_t value_at = html.find("data-value=\"", key_end) + 12;
    size_t value_end = html.find('"', value_at);
    size_t shown_at = html.find('>', value_end) + 1;
    size_t shown_end = html.find("</td>", shown_at);
    out.push_back({unescape(html.substr(at + open.size(), key_end - at - open.size())),
                   unescape(html.substr(value_at, value_end - value_at)),
                   unescape(html.substr(shown_at, shown_end - shown_at))});
  }
  return out;
}

struct Figure {
  std::string id, base64, caption;
};

// Every figure with an embedded PNG (parsed by hand: the data is too long for std::regex).
inline std::vector<Figure> figures(const std::string& html) {
  std::vector<Figure> out;
  auto between = [&](size_t from, const std::string& open, const std::string& close) {
    size_t a = html.find(open, from);
    size_t b = a == std::string::npos ? a : html.find(close, a + open.size());
    return b == std::string::npos ? std::string()
                                  : html.substr(a + open.size(), b - a - open.size());
  };
  for (size_t at = html.find("<figure "); at != std::string::npos;
       at = html.find("<figure ", at + 1)) {
    size_t end = html.find("</figure>", at);
    std::string id = between(at, "data-image=\"", "\"");
    std::string data = between(at, "src=\"data:image/png;base64,", "\"");
    if (data.empty() || html.find("src=\"data:", at) > end) data.clear();
    out.push_back({id, data, between(at, "<figcaption>", "</figcaption>")});
  }
  return out;
}

}  // namespace rtsim::test
