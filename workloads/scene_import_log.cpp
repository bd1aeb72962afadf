// An assimp Logger that keeps error messages and drops everything else.
#include "workloads/scene_import_log.h"

#include <assimp/DefaultLogger.hpp>
#include <assimp/Logger.hpp>

namespace rtsim {
namespace {

std::mutex import_mutex;

class ErrorCollector : public Assimp::Logger {
 public:
  explicit ErrorCollector(std::shared_ptr<std::vector<std::string>> errors)
      : errors_(std::move(errors)) {}
  bool attachStream(Assimp::LogStream*, unsigned) override { return false; }
  bool detachStream(Assimp::LogStream*, unsigned) override { return false; }

 protected:
  void OnDebug(const char*) override {}
  void OnVerboseDebug(const char*) override {}
  void OnInfo(const char*) override {}
  void OnWarn(const char*) override {}
  void OnError(const char* message) override { errors_->emplace_back(message); }

 private:
  std::shared_ptr<std::vector<std::string>> errors_;
};

}  // namespace

AssimpErrorLog::AssimpErrorLog()
    : lock_(import_mutex), errors_(std::make_shared<std::vector<std::string>>()) {
  Assimp::DefaultLogger::set(new ErrorCollector(errors_));  // owned by assimp until kill()
}

AssimpErrorLog::~AssimpErrorLog() {
  Assimp::DefaultLogger::kill();
}

}  // namespace rtsim
