#include "model/sc/fork_run.h"

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <exception>
#include <stdexcept>

#include "model/sc/stall_watchdog.h"
#include "traces/child_process.h"
#include "traces/error.h"

namespace rtsim {
namespace {

// A child's exit code: it returned, it threw InputError, SimStallError, anything else.
enum ChildExit { kDone = 0, kFailed = 1, kBadInput = 2, kStalled = 3 };

struct Child {
  pid_t pid = -1;
  int fd = -1;
  size_t task = 0;
};

void write_all(int fd, const std::string& text) {
  size_t done = 0;
  while (done < text.size()) {
    ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n <= 0) return;
    done += size_t(n);
  }
}

Child start_child(const std::function<std::string()>& fn, size_t task) {
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("run_in_children: pipe failed");
  pid_t pid = fork_child();
  if (pid < 0) throw std::runtime_error("run_in_children: fork failed");
  if (pid == 0) {
    close(fds[0]);
    int code = kDone;
    std::string text;
    try {
      text = fn();
    } catch (const InputError& e) {
      text = e.what();
      code = kBadInput;
    } catch (const SimStallError& e) {
      text = e.what();
      code = kStalled;
    } catch (const std::exception& e) {
      text = e.what();
      code = kFailed;
    } catch (...) {
      text = "unknown exception";
      code = kFailed;
    }
    write_all(fds[1], text);
    close(fds[1]);
    std::fflush(nullptr);
    _exit(code);
  }
  close(fds[1]);
  return {pid, fds[0], task};
}

struct Failure {
  int code = kDone;
  std::string message;
};

// Waits for the child and says how it ended.
Failure finish_child(const Child& c, const std::string& text) {
  close(c.fd);
  int status = 0;
  waitpid(c.pid, &status, 0);
  if (!WIFEXITED(status)) return {kFailed, "simulation child process died"};
  int code = WEXITSTATUS(status);
  if (code == kDone) return {};
  return {code == kBadInput || code == kStalled ? code : kFailed,
          text.empty() ? "simulation child process failed" : text};
}

}  // namespace

std::vector<std::string> run_in_children(const std::vector<std::function<std::string()>>& work,
                                         unsigned jobs) {
  jobs = std::max(jobs, 1u);
  std::vector<std::string> out(work.size());
  std::vector<Child> running;
  size_t next = 0;
  Failure failure;
  while (next < work.size() || !running.empty()) {
    while (failure.code == kDone && next < work.size() && running.size() < jobs) {
      running.push_back(start_child(work[next], next));
      ++next;
    }
    if (failure.code != kDone && running.empty()) break;
    std::vector<pollfd> fds;
    for (const Child& c : running) fds.push_back({c.fd, POLLIN, 0});
    if (poll(fds.data(), fds.size(), -1) < 0) continue;  // interrupted: poll again
    for (size_t i = running.size(); i-- > 0;) {
      if (!(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      char buffer[65536];
      ssize_t n = ::read(running[i].fd, buffer, sizeof buffer);
      if (n > 0) {
        out[running[i].task].append(buffer, size_t(n));
        continue;
      }
      if (n < 0 && errno == EINTR) continue;
      Failure f = finish_child(running[i], out[running[i].task]);
      if (f.code != kDone && failure.code == kDone) failure = f;
      running.erase(running.begin() + ptrdiff_t(i));
    }
  }
  if (failure.code == kBadInput) throw InputError(failure.message);
  if (failure.code == kStalled) throw SimStallError(failure.message);
  if (failure.code != kDone) throw std::runtime_error(failure.message);
  return out;
}

std::string run_in_child(const std::function<std::string()>& fn) {
  return run_in_children({fn}, 1)[0];
}

}  // namespace rtsim
