// Mock neighbours of an RT unit for tests without SystemC: a memory with a fixed latency that
// records every request, and a ray supply over a vector that records every retirement.
#pragma once

#include <memory>
#include <vector>

#include "model/sched/dispatcher.h"
#include "model/sched/ray_supply.h"

namespace rtsim::test {

// deferred: every read returns kPending and is answered (latency cycles after it was made)
// only by answer_all(), as an L1 miss is by the L2.
struct MockRayMemory : MemoryTarget {
  explicit MockRayMemory(Cycle latency, bool deferred = false)
      : latency(latency), deferred(deferred) {}
  Cycle read(uint64_t addr, uint32_t bytes, Cycle now, ReadClient* client, uint64_t token,
             ReadCharge&) override {
    reads.push_back({addr, bytes, now});
    if (!deferred) return now + latency;
    unanswered.push_back({client, token, now + latency});
    return kPending;
  }
  void answer_all() {
    std::vector<Answer> now;
    now.swap(unanswered);
    for (const Answer& a : now) a.client->read_done(a.token, a.ready, {});
  }
  void write(uint64_t addr, uint32_t bytes, Cycle now) override {
    writes.push_back({addr, bytes, now});
  }
  void prefetch(uint64_t addr, uint32_t bytes, Cycle now) override {
    prefetches.push_back({addr, bytes, now});
  }
  struct Request {
    uint64_t addr;
    uint32_t bytes;
    Cycle at;
  };
  struct Answer {
    ReadClient* client;
    uint64_t token;
    Cycle ready;
  };
  Cycle latency;
  bool deferred;
  std::vector<Request> reads, writes, prefetches;
  std::vector<Answer> unanswered;
};

// What a retired ray left: its answer and when.
struct Retired {
  uint64_t sequence;
  Hit hit;
  uint32_t prim;
  TraversalCounters counters;
  RayCost cost;
  Cycle cycle;
};

struct RecordingListener : RayRetireListener {
  explicit RecordingListener(const TraversalUnit& unit) : unit(unit) {}
  void retired(const RayContext& ray, Cycle now) override {
    done.push_back({ray.sequence, unit.result(ray.state, ray.ray), ray.state.prim,
                    ray.state.counters, ray.cost, now});
  }
  const TraversalUnit& unit;
  std::vector<Retired> done;
};

// A dispatcher over a vector of rays, with its own pool and listener.
struct MockSupply {
  MockSupply(std::vector<Ray> rays_in, const TraversalUnit& unit, uint32_t pool_size,
             DispatchConfig config = {1000.0, 0})
      : rays(std::move(rays_in)),
        source(rays),
        pool(pool_size),
        listener(unit),
        dispatcher(config, source, pool, &listener) {}
  std::vector<Ray> rays;
  VectorRaySource source;
  RayContextPool pool;
  RecordingListener listener;
  RayDispatcher dispatcher;
};

}  // namespace rtsim::test
