#include "model/multi/child_pool.h"

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <exception>
#include <stdexcept>

namespace rtsim::multi {
namespace {

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
  std::fflush(nullptr);  // no buffered output is written twice
  pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("run_in_children: fork failed");
  if (pid == 0) {
    close(fds[0]);
    int code = 0;
    std::string text;
    try {
      text = fn();
    } catch (const std::exception& e) {
      text = e.what();
      code = 1;
    } catch (...) {
      text = "unknown exception";
      code = 1;
    }
    write_all(fds[1], text);
    close(fds[1]);
    std::fflush(nullptr);
    _exit(code);
  }
  close(fds[1]);
  return {pid, fds[0], task};
}

// Waits for the child; an empty string if it succeeded, else why not.
std::string finish_child(const Child& c, const std::string& text) {
  close(c.fd);
  int status = 0;
  waitpid(c.pid, &status, 0);
  if (!WIFEXITED(status)) return "simulation child process died";
  if (WEXITSTATUS(status) != 0) return text.empty() ? "simulation child process failed" : text;
  return "";
}

}  // namespace

std::vector<std::string> run_in_children(const std::vector<std::function<std::string()>>& work,
                                         unsigned jobs) {
  jobs = std::max(jobs, 1u);
  std::vector<std::string> out(work.size());
  std::vector<Child> running;
  size_t next = 0;
  std::string failure;
  while (next < work.size() || !running.empty()) {
    while (failure.empty() && next < work.size() && running.size() < jobs) {
      running.push_back(start_child(work[next], next));
      ++next;
    }
    if (!failure.empty() && running.empty()) break;
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
      std::string why = finish_child(running[i], out[running[i].task]);
      if (!why.empty() && failure.empty()) failure = why;
      running.erase(running.begin() + ptrdiff_t(i));
    }
  }
  if (!failure.empty()) throw std::runtime_error(failure);
  return out;
}

}  // namespace rtsim::multi
