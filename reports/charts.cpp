#include "reports/charts.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <fmt/core.h>

#include "traces/child_process.h"

namespace rtsim::reports {
namespace {

std::string env_or(const char* name, const std::string& fallback) {
  const char* value = std::getenv(name);
  return value && *value ? value : fallback;
}

std::string last_line(const std::string& text) {
  size_t end = text.find_last_not_of("\n ");
  if (end == std::string::npos) return "";
  size_t start = text.rfind('\n', end);
  return text.substr(start == std::string::npos ? 0 : start + 1, end + 1 - (start + 1));
}

}  // namespace

std::string charts_dir() {
  return env_or("RTSIM_CHARTS_DIR", RTSIM_CHARTS_DIR);
}

ChartRun run_chart_script(const std::string& script, const std::vector<std::string>& args) {
  std::string python = env_or("RTSIM_PYTHON", "/usr/bin/python3");
  std::string path = charts_dir() + "/" + script;
  if (access(python.c_str(), X_OK) != 0)
    return {false, python + " not found (install python3-matplotlib: scripts/install-deps)"};
  if (!std::filesystem::exists(path)) return {false, path + " not found"};
  std::vector<std::string> words{python, path};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  int fds[2];
  if (pipe(fds) != 0) return {false, "pipe failed"};
  pid_t pid = fork_child();
  if (pid < 0) return {false, "fork failed"};
  if (pid == 0) {
    close(fds[0]);
    dup2(fds[1], STDERR_FILENO);
    dup2(fds[1], STDOUT_FILENO);
    setenv("MPLBACKEND", "Agg", 1);
    execv(python.c_str(), argv.data());
    _exit(127);
  }
  close(fds[1]);
  std::string output;
  char buffer[4096];
  for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) > 0;) output.append(buffer, size_t(n));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return {true, ""};
  return {false, script + ": " + last_line(output)};
}

int chart_exit_code(const ChartRun& run) {
  if (run.ok) return 0;
  fmt::print(stderr, "rtsim: charts failed: {}\n", run.message);
  return 1;
}

}  // namespace rtsim::reports
