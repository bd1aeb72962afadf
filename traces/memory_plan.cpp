#include "traces/memory_plan.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include <fmt/core.h>

#include "traces/byte_size.h"
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

// Address space left under `ulimit -v` (RLIMIT_AS): the limit less what this process already
// maps (/proc/self/statm's first field, in pages); an allocation beyond it fails at once.
uint64_t address_space_left_bytes() {
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY)
    return std::numeric_limits<uint64_t>::max();
  std::ifstream in("/proc/self/statm");
  uint64_t pages = 0;
  in >> pages;
  uint64_t mapped = pages * uint64_t(sysconf(_SC_PAGESIZE));
  return limit.rlim_cur > mapped ? limit.rlim_cur - mapped : 0;
}

}  // namespace

uint64_t available_memory_bytes() {
  // The address-space limit is hard: an allocation beyond it fails whatever else is planned.
  uint64_t address_space = address_space_left_bytes();
  if (const char* text = std::getenv("RTSIM_MAX_MEMORY"))
    return std::min(parse_byte_size(text, "RTSIM_MAX_MEMORY"), address_space);
  uint64_t available = meminfo_bytes("MemAvailable");
  if (available == 0) available = std::numeric_limits<uint64_t>::max();  // unknown: do not refuse
  return std::min({available, cgroup_limit_bytes(), address_space});
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
