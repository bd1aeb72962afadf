#include "reports/process_pool.h"

#include <fcntl.h>
#include <sched.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <thread>

#include "traces/child_process.h"
#include "traces/hash.h"

namespace rtsim::reports {
namespace {

// In a forked child: becomes argv (argv[0] a full path), or exits 127.
[[noreturn]] void exec_child(std::vector<std::string> words) {
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  execv(argv[0], argv.data());
  _exit(127);
}

pid_t start(const ProcessJob& job) {
  pid_t pid = fork_child();
  if (pid != 0) return pid;
  int fd = open(job.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd >= 0) {
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    close(fd);
  }
  exec_child(job.argv);
}

}  // namespace

std::string self_executable() {
  return std::filesystem::read_symlink("/proc/self/exe").string();
}

std::string executable_fingerprint() {
  static const std::string fingerprint = [] {
    std::ifstream in(self_executable(), std::ios::binary);
    std::vector<char> buffer(1 << 20);
    uint64_t hash = fnv1a64(nullptr, 0);  // the offset basis
    while (in.read(buffer.data(), std::streamsize(buffer.size())) || in.gcount() > 0)
      hash = fnv1a64(buffer.data(), size_t(in.gcount()), hash);
    return hex64(hash);
  }();
  return fingerprint;
}

std::vector<std::string> run_child_argv(const std::string& trace_dir, const std::string& out_dir,
                                        const std::string& fidelity, uint32_t sample_rate,
                                        const std::string& config) {
  std::vector<std::string> argv{self_executable(),
                                "run",
                                "--from-trace",
                                trace_dir,
                                "-o",
                                out_dir,
                                "--report",
                                "json",
                                "-q",
                                "--fidelity",
                                fidelity,
                                "--sample-rate",
                                std::to_string(sample_rate)};
  if (!config.empty()) argv.insert(argv.end(), {"--config", config});
  return argv;
}

std::string find_on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/local/bin:/usr/bin:/bin";
  for (size_t start = 0; start <= dirs.size();) {
    size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    std::string candidate = dirs.substr(start, end - start) + "/" + program;
    if (end > start && access(candidate.c_str(), X_OK) == 0) return candidate;
    start = end + 1;
  }
  return "";
}

CommandOutput run_command(const std::vector<std::string>& argv) {
  char out_name[] = "/tmp/rtsim-command-XXXXXX", err_name[] = "/tmp/rtsim-command-XXXXXX";
  int out_fd = mkstemp(out_name), err_fd = mkstemp(err_name);
  CommandOutput result{127, "", ""};
  if (out_fd >= 0 && err_fd >= 0) {
    pid_t pid = fork_child();
    if (pid == 0) {
      dup2(out_fd, STDOUT_FILENO);
      dup2(err_fd, STDERR_FILENO);
      exec_child(argv);
    }
    int status = 0;
    if (pid > 0 && waitpid(pid, &status, 0) == pid)
      result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    auto slurp = [](const char* name) {
      std::ifstream in(name);
      return std::string(std::istreambuf_iterator<char>(in), {});
    };
    result.stdout_text = slurp(out_name);
    result.stderr_text = slurp(err_name);
  }
  for (auto [fd, name] : {std::pair{out_fd, out_name}, {err_fd, err_name}})
    if (fd >= 0) {
      close(fd);
      unlink(name);
    }
  return result;
}

uint32_t local_cores() {
  // The CPUs this process may run on: a taskset, container or Slurm cpuset gives fewer than the
  // machine has, and points beyond them only take turns.
  cpu_set_t cpus;
  if (sched_getaffinity(0, sizeof cpus, &cpus) == 0) return uint32_t(std::max(1, CPU_COUNT(&cpus)));
  return std::max(1u, std::thread::hardware_concurrency());
}

void run_processes(const std::vector<ProcessJob>& jobs, uint32_t parallel,
                   const std::function<void(size_t, int, double)>& done) {
  using Clock = std::chrono::steady_clock;
  std::map<pid_t, std::pair<size_t, Clock::time_point>> running;
  size_t next = 0;
  while (next < jobs.size() || !running.empty()) {
    while (next < jobs.size() && running.size() < std::max(parallel, 1u)) {
      pid_t pid = start(jobs[next]);
      if (pid < 0) {
        done(next++, 127, 0.0);
        continue;
      }
      running[pid] = {next++, Clock::now()};
    }
    int status = 0;
    pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) break;
    auto it = running.find(pid);
    if (it == running.end()) continue;
    auto [index, started] = it->second;
    running.erase(it);
    done(index, WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status),
         std::chrono::duration<double>(Clock::now() - started).count());
  }
}

}  // namespace rtsim::reports
