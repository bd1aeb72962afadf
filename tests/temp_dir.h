// Scratch folders for tests: a private folder under the system's temp directory, removed with
// everything in it when the object dies, and one such folder per test process.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace rtsim::test {

class TempDir {
 public:
  TempDir() {
    static int counter = 0;
    path_ = std::filesystem::temp_directory_path() /
            ("rtsim-scratch-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  // Writes contents (text or bytes) to name inside the folder and returns the full path.
  std::string write(const std::string& name, const std::string& contents) const {
    std::string file = (path_ / name).string();
    std::ofstream(file, std::ios::binary) << contents;
    return file;
  }
  std::string path(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

// A path inside this test process's folder, which is removed when the process exits.
inline std::string scratch_path(const std::string& name) {
  static const TempDir dir;
  return dir.path(name);
}

}  // namespace rtsim::test
