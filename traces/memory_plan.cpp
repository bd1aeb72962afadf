#include "traces/memory_plan.h"

#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include <fmt/core.h>

#include "traces/error.h"

namespace rtsim {
namespace {

// A value in kB from /proc/meminfo ("MemAvailable:   23778528 kB"), in bytes; 0 if absent.
uint64_t meminfo_bytes(const std::string& key) {
  std::ifstream in("/proc/meminfo");
  std::string name;
  uint64_t kb = 0;
  std::string unit;
  while (in >> name >> kb >> unit)
    if (name == key + ":") return kb * 1024;
  return 0;
}

uint64_t cgroup_limit_bytes() {
  std::ifstream in("/sys/fs/cgroup/memory.max");
  uint64_t limit = 0;
  if (in >> limit) return limit;  // "max" (no limit) does not parse
  return std::numeric_limits<uint64_t>::max();
}

}  // namespace

uint64_t available_memory_bytes() {
  if (const char* text = std::getenv("RTSIM_MAX_MEMORY")) {
    char* end = nullptr;
    unsigned long long value = std::strtoull(text, &end, 10);
    if (end != text && *end == '\0') return value;
    throw InputError(fmt::format("RTSIM_MAX_MEMORY: expected a number of bytes, got '{}'", text));
  }
  uint64_t available = meminfo_bytes("MemAvailable");
  if (available == 0) return std::numeric_limits<uint64_t>::max();  // unknown: do not refuse
  return std::min(available, cgroup_limit_bytes());
}

void require_memory(uint64_t bytes, const std::string& source, const std::string& what,
                    const std::string& advice) {
  uint64_t available = available_memory_bytes();
  if (bytes <= available) return;
  throw_input_error(source, "",
                    fmt::format("{} needs about {:.1f} GB of memory, more than the {:.1f} GB "
                                "available; {}",
                                what, double(bytes) / 1e9, double(available) / 1e9, advice));
}

}  // namespace rtsim
