// Private to workloads/: collects the errors assimp logs while it imports. Some readers log an
// error and carry on with repaired data (the OFF reader clamps an out-of-range vertex index),
// which a successful ReadFile does not reveal.
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace rtsim {

// Installs a logger for its lifetime. assimp's logger is a process-wide singleton, so imports
// are serialized while one is alive.
class AssimpErrorLog {
 public:
  AssimpErrorLog();
  ~AssimpErrorLog();
  AssimpErrorLog(const AssimpErrorLog&) = delete;
  AssimpErrorLog& operator=(const AssimpErrorLog&) = delete;

  // The errors logged so far, oldest first.
  const std::vector<std::string>& errors() const { return *errors_; }

 private:
  std::unique_lock<std::mutex> lock_;
  std::shared_ptr<std::vector<std::string>> errors_;
};

}  // namespace rtsim
