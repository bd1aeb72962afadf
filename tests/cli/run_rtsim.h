// Runs the rtsim executable (or another of the project's) as a user would, capturing exit code,
// stdout and stderr.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace rtsim::test {

struct RunResult {
  int exit_code = -1;
  std::string out, err;
};

inline std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// args is appended to the executable's path as shell words; quote them as a shell would need.
inline RunResult run_program(const std::string& executable, const std::string& args) {
  std::string base = "/tmp/rtsim-cli-" + std::to_string(getpid());
  std::string cmd = executable + " " + args + " >" + base + ".out 2>" + base + ".err";
  int status = std::system(cmd.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(base + ".out");
  r.err = slurp(base + ".err");
  std::remove((base + ".out").c_str());
  std::remove((base + ".err").c_str());
  return r;
}

inline RunResult run_rtsim(const std::string& args) {
  return run_program(RTSIM_EXE, args);
}

inline int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

inline std::string first_line(const std::string& s) {
  return s.substr(0, s.find('\n'));
}

}  // namespace rtsim::test
