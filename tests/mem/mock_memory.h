// A mock level below a cache: fixed latency, records every request.
#pragma once

#include <vector>

#include "model/mem/memory_level.h"

namespace rtsim::test {

struct MockMemory : MemoryLevel {
  explicit MockMemory(Cycle latency) : latency(latency) {}
  Cycle read(uint64_t addr, uint32_t bytes, Cycle now) override {
    requests.push_back({addr, bytes, now});
    return now + latency;
  }
  struct Request {
    uint64_t addr;
    uint32_t bytes;
    Cycle at;
  };
  Cycle latency;
  std::vector<Request> requests;
};

}  // namespace rtsim::test
