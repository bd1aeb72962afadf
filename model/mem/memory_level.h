// The contracts between levels of the memory hierarchy, in plain C++ (no SystemC).
//
// MemoryTarget is a cache level as its requesters see it. A read of `bytes` at `addr` made at
// cycle `at` returns the cycle its data is ready when that is known at once (a hit), or
// kPending: then the target calls client->read_done(token, ready, charge) later, never during
// the read call itself. A target serves calls in the order they are made, so the caller makes
// them in non-decreasing `at` (an RT unit in its local time; the shared L2's module in
// simulated-time order, model/sc/shared_levels_module.h), and a request dated earlier is never
// delayed by one dated later. Writes are posted: nobody waits for them.
// It is the one interface below a cache: a unit's next own level, the shared levels' crossbar
// (model/sc/tlm_memory.h), the next shared level's instance, and every DRAM below the last level
// are MemoryTargets: the simple DRAM (DramTarget, model/mem/dram.h), the banked DRAM by call
// (model/sc/banked_dram_module.h), and the TLM-2.0 `out` socket of the shared levels in its
// loosely- or approximately-timed protocol (model/sc/shared_levels_module.h).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace rtsim {

using Cycle = uint64_t;
constexpr Cycle kPending = ~Cycle(0);  // a read whose ready cycle is not known yet
// Local memory (the RT units' stack spills) lives at and above this address; caches count its
// traffic apart (model/sched/hardware_stack.h places the spills).
constexpr uint64_t kLocalMemoryBase = 0x7000'0000'0000ull;
// Textures the shader core reads (any-hit alpha tests, traces/alpha.h) live at and above this
// address, below local memory.
constexpr uint64_t kTextureBase = 0x6000'0000'0000ull;
// What hit shading reads (G-buffer, textures, payload; model/sched/shader_core.h) lives at and
// above this address, below textures.
constexpr uint64_t kShadingBase = 0x5000'0000'0000ull;

// How far into the host's caches a hint brings a line: all the way (the default), or into its
// second level only, for a record read an event from now (a first-level hint would push out
// what the current event reads).
constexpr int kHostL1 = 3, kHostL2 = 2;

// Asks the host to bring [p, p + bytes) into its caches, a prefetch every `step` bytes: a hint
// for a record the simulation reads later (a lookup, a step), which changes nothing it computes.
// With thousands of requests and rays in flight, the records they touch have left the host's
// caches by the time they are read; a hint given while other work runs hides that wait.
template <int Level = kHostL1>
inline void prefetch_span(const void* p, size_t bytes, size_t step) {
  auto first = static_cast<const char*>(p);
  for (const char* q = first; q < first + bytes; q += step) __builtin_prefetch(q, 0, Level);
}

// The most cache levels a hierarchy has ([[memory.level]], model/mem/hierarchy.h): a read's
// charge keeps a count per level in place, so that charging one is an add, not an allocation.
constexpr uint32_t kMaxCacheLevels = 6;

// What reads cost at each level of the memory hierarchy: a level counts its own block accesses
// and hits (level 0 is the RT unit's first); the level above DRAM counts the bytes it fetched.
// The same record at three widths: one read's charge (a few blocks; kept in a miss's records,
// so small), a ray's cost and sums over many rays. `depth` bounds the levels counted so far, so
// that adding a read that hit the first level touches that level alone (the common case).
template <typename Count, typename Bytes>
struct LevelCounts {
  std::array<Count, kMaxCacheLevels> accesses{}, hits{};
  Bytes dram_bytes = 0;
  uint8_t depth = 0;  // levels 0 .. depth - 1 may hold counts; the others are 0
  void add(uint32_t level, Count level_accesses, Count level_hits) {
    accesses[level] += level_accesses;
    hits[level] += level_hits;
    if (depth <= level) depth = uint8_t(level + 1);
  }
  template <typename C, typename B>
  LevelCounts& operator+=(const LevelCounts<C, B>& o) {
    for (uint32_t i = 0; i < o.depth; ++i) {
      accesses[i] += Count(o.accesses[i]);
      hits[i] += Count(o.hits[i]);
    }
    if (depth < o.depth) depth = o.depth;
    dram_bytes += Bytes(o.dram_bytes);
    return *this;
  }
  template <typename C, typename B>
  LevelCounts& operator-=(const LevelCounts<C, B>& o) {
    for (uint32_t i = 0; i < o.depth; ++i) {
      accesses[i] -= Count(o.accesses[i]);
      hits[i] -= Count(o.hits[i]);
    }
    if (depth < o.depth) depth = o.depth;
    dram_bytes -= Bytes(o.dram_bytes);
    return *this;
  }
  bool empty() const {
    for (uint32_t i = 0; i < depth; ++i)
      if (accesses[i] | hits[i]) return false;
    return dram_bytes == 0;
  }
  Count misses(uint32_t level) const { return Count(accesses[level] - hits[level]); }
};
using ReadCharge = LevelCounts<uint16_t, uint32_t>;  // one read
using RayReads = LevelCounts<uint32_t, uint64_t>;    // one ray's reads
using ReadCounts = LevelCounts<uint64_t, uint64_t>;  // sums

// Where a read comes from, for the stall dump: the RT unit, its ray slot and the ray (its
// sequence number in the stream). kUnknown where a field does not apply (a prefetch has no ray).
struct ReadOrigin {
  static constexpr uint64_t kUnknown = ~uint64_t(0);
  uint64_t unit = kUnknown, slot = kUnknown, ray = kUnknown;
};

// " for rt0 slot 3 ray 17", or " for no ray" (a prefetch, a shading read).
inline std::string origin_text(const ReadOrigin& o) {
  if (o.unit == ReadOrigin::kUnknown) return " for no ray";
  std::string text = " for rt" + std::to_string(o.unit);
  if (o.slot != ReadOrigin::kUnknown) text += " slot " + std::to_string(o.slot);
  if (o.ray != ReadOrigin::kUnknown) text += " ray " + std::to_string(o.ray);
  return text;
}

// Who waits for a read that did not complete at once.
class ReadClient {
 public:
  virtual ~ReadClient() = default;
  // The read made with `token` has its data at `ready`; charge is what it cost beyond what the
  // read call returned.
  virtual void read_done(uint64_t token, Cycle ready, const ReadCharge& charge) = 0;
  // A hint that read_done(token, ...) comes soon: the client may ask the host's memory (kHostL2)
  // for what answering it touches. Changes nothing modelled.
  virtual void prime_done(uint64_t token) const { (void)token; }
  // Where the read made with `token` comes from (a level passes the question to its own
  // requester). For the stall dump only: slow is fine.
  virtual ReadOrigin origin(uint64_t token) const {
    (void)token;
    return {};
  }
};

class MemoryTarget {
 public:
  virtual ~MemoryTarget() = default;
  // charge receives the cost known at once. Returns the ready cycle or kPending.
  virtual Cycle read(uint64_t addr, uint32_t bytes, Cycle at, ReadClient* client, uint64_t token,
                     ReadCharge& charge) = 0;
  virtual void write(uint64_t addr, uint32_t bytes, Cycle at) = 0;
  // A clean line the level above evicted, for a level filled by evictions (fill = "victim"):
  // it is placed without a fetch. Nobody waits for it; a level of another kind never gets one.
  virtual void fill(uint64_t addr, uint32_t bytes, Cycle at) { (void)addr, (void)bytes, (void)at; }
  // A hint to fetch [addr, addr + bytes) ahead of demand (treelet prefetching); nobody waits
  // for it. A level that does not prefetch ignores it.
  virtual void prefetch(uint64_t addr, uint32_t bytes, Cycle at) {
    (void)addr, (void)bytes, (void)at;
  }
};

}  // namespace rtsim
