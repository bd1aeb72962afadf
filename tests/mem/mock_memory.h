// A mock level below a cache: a fixed latency, answered at once or, when deferred, only when
// the test says so (a level whose data time is not known yet); records every request.
#pragma once

#include <vector>

#include "model/mem/memory_level.h"

namespace rtsim::test {

struct MockMemory : MemoryTarget {
  explicit MockMemory(Cycle latency, bool deferred = false)
      : latency(latency), deferred(deferred) {}
  Cycle read(uint64_t addr, uint32_t bytes, Cycle at, ReadClient* client, uint64_t token,
             ReadCharge&) override {
    requests.push_back({addr, bytes, at, client, token});
    return deferred ? kPending : at + latency;
  }
  void write(uint64_t addr, uint32_t bytes, Cycle at) override {
    writes.push_back({addr, bytes, at, nullptr, 0});
  }
  // Deferred mode: request i's data is ready at `ready`.
  void answer(size_t i, Cycle ready) {
    requests[i].client->read_done(requests[i].token, ready, {});
  }
  struct Request {
    uint64_t addr;
    uint32_t bytes;
    Cycle at;
    ReadClient* client;
    uint64_t token;
  };
  Cycle latency;
  bool deferred;
  std::vector<Request> requests, writes;
};

// A client that records every completion.
struct RecordingClient : ReadClient {
  void read_done(uint64_t token, Cycle ready, const ReadCharge& charge) override {
    done.push_back({token, ready, charge});
  }
  struct Done {
    uint64_t token;
    Cycle ready;
    ReadCharge charge;
  };
  std::vector<Done> done;
};

}  // namespace rtsim::test
