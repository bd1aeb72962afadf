#include "traces/output_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "traces/error.h"

namespace rtsim {

namespace fs = std::filesystem;

void create_output_folder(const std::string& dir) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error) throw_input_error(dir, "", "cannot create the output folder: " + error.message());
  if (!fs::is_directory(dir, error))
    throw_input_error(dir, "", "cannot create the output folder: a file of that name exists");
  if (::access(dir.c_str(), W_OK) != 0)
    throw_input_error(dir, "", "the output folder is not writable");
}

OutputFile::OutputFile(const std::string& path) : target_(path) {
  // Follow links (also to a file that does not exist yet), as open() would; at most 40, as Linux.
  fs::path target = path;
  std::error_code error;
  for (int depth = 0; depth < 40 && fs::is_symlink(fs::symlink_status(target, error)); ++depth) {
    fs::path next = fs::read_symlink(target, error);
    if (error) break;
    target = next.is_absolute() ? next : target.parent_path() / next;
  }
  target_ = target.string();
  struct stat info {};
  bool exists = ::stat(target_.c_str(), &info) == 0;
  renames_ = !exists || S_ISREG(info.st_mode);
  sequential_ = exists && (S_ISFIFO(info.st_mode) || S_ISSOCK(info.st_mode));
  write_path_ = renames_ ? target_ + ".tmp-" + std::to_string(getpid()) : target_;
}

bool OutputFile::commit() {
  return !renames_ || std::rename(write_path_.c_str(), target_.c_str()) == 0;
}

void OutputFile::discard() {
  if (renames_) std::remove(write_path_.c_str());
}

}  // namespace rtsim
