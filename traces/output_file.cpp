#include "traces/output_file.h"

#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>

#include "traces/error.h"

namespace rtsim {

namespace fs = std::filesystem;

namespace {

// The temporaries being written, readable from a signal handler: an entry's owner is 0 when
// free, -1 while its path is filled in, else the pid of the process writing it (a forked child
// inherits the table and must not remove its parent's files).
struct Pending {
  std::atomic<pid_t> owner{0};
  char path[PATH_MAX];
};
constexpr int kPendingSlots = 64;
Pending g_pending[kPendingSlots];

int remember(const std::string& path) {
  if (path.size() >= PATH_MAX) return -1;
  for (int i = 0; i < kPendingSlots; ++i) {
    pid_t free = 0;
    if (!g_pending[i].owner.compare_exchange_strong(free, -1)) continue;
    std::memcpy(g_pending[i].path, path.c_str(), path.size() + 1);
    g_pending[i].owner.store(getpid());
    return i;
  }
  return -1;  // more at once than the table holds: the destructor still removes it
}

void forget(int slot) {
  if (slot >= 0) g_pending[slot].owner.store(0);
}

void remove_pending_and_die(int signal_number) {
  pid_t self = getpid();
  for (Pending& p : g_pending)
    if (p.owner.load() == self) ::unlink(p.path);
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}

bool process_exists(pid_t pid) {
  return ::kill(pid, 0) == 0 || errno != ESRCH;
}

// Removes NAME.tmp-PID beside target for every PID that is not a running process.
void remove_stale_temporaries(const fs::path& target) {
  std::string prefix = target.filename().string() + ".tmp-";
  fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code error;
  for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error)) {
    std::string name = it->path().filename().string();
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
    std::string digits = name.substr(prefix.size());
    if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    if (!process_exists(pid_t(std::stol(digits)))) fs::remove(it->path(), error);
  }
}

}  // namespace

void remove_temporaries_on_signals() {
  struct sigaction action {};
  action.sa_handler = remove_pending_and_die;
  sigemptyset(&action.sa_mask);
  for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(signal_number, &action, nullptr);
}

void create_output_folder(const std::string& dir) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error) throw_input_error(dir, "", "cannot create the output folder: " + error.message());
  if (!fs::is_directory(dir, error))
    throw_input_error(dir, "", "cannot create the output folder: a file of that name exists");
  if (::access(dir.c_str(), W_OK) != 0)
    throw_input_error(dir, "", "the output folder is not writable");
}

void lock_output_folder(const std::string& dir, const std::string& command) {
  static std::set<std::string> held;  // canonical paths of the folders this process locked
  std::error_code error;
  std::string key = fs::weakly_canonical(dir, error).string();
  if (held.count(key)) return;
  std::string path = (fs::path(dir) / ".rtsim.lock").string();
  int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw_input_error(dir, "", "cannot create the folder's lock file " + path);
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    std::string owner;
    std::getline(std::ifstream(path), owner);
    ::close(fd);
    throw_input_error(dir, "",
                      "another rtsim (pid " + (owner.empty() ? "unknown" : owner) +
                          ") is writing this folder; wait for it to finish, or give " + command +
                          " another -o");
  }
  // The pid is only for another process's message: the lock holds without it.
  std::string pid = std::to_string(getpid()) + "\n";
  if (::ftruncate(fd, 0) == 0) (void)!::write(fd, pid.data(), pid.size());
  held.insert(key);  // fd stays open: the lock lasts as long as the process
}

std::string output_target(const std::string& path) {
  fs::path target = path;
  std::error_code error;
  for (int depth = 0; depth < 40 && fs::is_symlink(fs::symlink_status(target, error)); ++depth) {
    fs::path next = fs::read_symlink(target, error);
    if (error) break;
    target = next.is_absolute() ? next : target.parent_path() / next;
  }
  return target.string();
}

bool writes_regular_file(const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) != 0 || S_ISREG(info.st_mode);
}

void check_output_path(const std::string& path, const std::string& option) {
  std::error_code error;
  std::string target = output_target(path);
  if (fs::is_directory(target, error))
    throw_input_error(path, option, "is a folder; give a file path");
  if (!writes_regular_file(target)) return;
  fs::path folder = fs::path(target).parent_path();
  if (folder.empty()) folder = ".";
  if (!fs::is_directory(folder, error))
    throw_input_error(path, option, "its folder " + folder.string() + " does not exist");
  if (::access(folder.c_str(), W_OK) != 0)
    throw_input_error(path, option, "its folder " + folder.string() + " is not writable");
}

namespace {

// What a path names: its device and inode where it exists, else its absolute path with links
// resolved.
std::string file_identity(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0)
    return std::to_string(info.st_dev) + ":" + std::to_string(info.st_ino);
  std::error_code error;
  return fs::weakly_canonical(fs::absolute(output_target(path), error), error).string();
}

}  // namespace

void refuse_overwriting(const std::vector<NamedPath>& inputs,
                        const std::vector<NamedPath>& outputs) {
  std::vector<std::pair<std::string, const NamedPath*>> named;  // identity, and who named it
  for (const NamedPath& input : inputs)
    if (!input.path.empty()) named.emplace_back(file_identity(input.path), &input);
  for (const NamedPath& output : outputs) {
    if (output.path.empty() || !writes_regular_file(output.path)) continue;
    std::string identity = file_identity(output.path);
    for (const auto& [other_identity, other] : named)
      if (other_identity == identity)
        throw_input_error(output.path, output.option,
                          "is the same file as " + other->option + " (" + other->path +
                              "); writing it would replace that; choose another " + output.option);
    named.emplace_back(identity, &output);
  }
}

OutputFile::OutputFile(const std::string& path) : target_(output_target(path)) {
  struct stat info {};
  bool exists = ::stat(target_.c_str(), &info) == 0;
  renames_ = !exists || S_ISREG(info.st_mode);
  sequential_ = exists && (S_ISFIFO(info.st_mode) || S_ISSOCK(info.st_mode));
  write_path_ = renames_ ? target_ + ".tmp-" + std::to_string(getpid()) : target_;
  if (!renames_) return;
  remove_stale_temporaries(target_);
  pending_ = remember(write_path_);
}

OutputFile::~OutputFile() {
  discard();
}

bool OutputFile::commit() {
  if (!renames_ || done_) return !renames_;
  if (std::rename(write_path_.c_str(), target_.c_str()) != 0) return false;
  done_ = true;
  forget(pending_);
  return true;
}

void OutputFile::discard() {
  if (!renames_ || done_) return;
  std::remove(write_path_.c_str());
  done_ = true;
  forget(pending_);
}

}  // namespace rtsim
