// The cache levels that several RT units share (model/mem/hierarchy.h: group and shared scopes;
// the L2 of a two-level machine) and the way to DRAM, as one sc_module that serves every request
// at every such level in simulated-time order. Each level has one instance per group of units
// (one for a shared level): a crossbar from its requesters (model/mem/crossbar.h) and the
// level's address-hashed slices behind it. The requesters of an instance are the RT units' own
// last levels (model/sc/tlm_memory.h: connect) or the instances of the level above; TLM-2.0
// approximately-timed initiators bound to `in` are requesters of the first level's instance 0:
// BEGIN_REQ dated by its delay, answered END_REQ at once (the request queue has no bound).
// Every request is one record (model/mem/mem_request.h) in the module's pool, from the moment
// it is sent until it is answered or served: its instance, port and slice, whom its answer goes
// to (typed, not an integer that changes meaning at every hop) and what it waits for since which
// cycle; the calendar holds small jobs naming a record. A slice's miss and eviction, and a
// memory port's request, become a record at the next level's instance or at the DRAM, whose
// answer goes to that slice's miss. The answer to a read is sent as soon as the data's cycle is
// known (a hit: when the request is served; a miss: when the level below has answered), dated
// by the data's cycle: its client's read_done for a connected unit, a job at the data's cycle
// for the level above (so that the level above sees its answers in time order too), BEGIN_RESP
// with a delay for a TLM initiator. Writes and victim fills are posted. waiting() lists the
// records in use, for the stall dump.
// Why a queue: units run up to a quantum ahead of simulated time and a miss that waited for an
// MSHR leaves later than it was made, so requests arrive out of time order. The module holds
// them in an event calendar and serves each at its own cycle, when simulated time reaches it;
// every cache (model/mem/cache.h) and the DRAM below therefore see their requests in
// non-decreasing cycle order, and a request dated earlier is never delayed by one dated later.
// A miss at one level is a request at the next, at the miss's cycle, in the same calendar.
// The DRAM is reached at the request's own cycle through one interface, a MemoryTarget
// (model/mem/memory_level.h), of which there are three: the banked DRAM by call
// (connect_memory; model/sc/banked_dram_module.h), which answers each read's data cycle at least
// `lead` cycles before it; and `out`, in one of two protocols: by default the base protocol's
// blocking transport (loosely timed: the data's cycle at once), so any loosely-timed TLM memory
// can be bound there; after use_timed_memory(lead), the approximately-timed one (a DRAMSys-class
// model): BEGIN_REQ through nb_transport_fw, and the data's cycle in the delay of BEGIN_RESP,
// sent at least `lead` cycles before it (0: at that cycle). With a lead the module serves at
// most lead + 1 cycles ahead, so an answer is never dated before a job already served; one dated
// inside the window already served is served at once, with what it starts there, in cycle order.
// A request crosses the crossbar to its slice (slice_of: a hash of the line address; a request
// must not span lines, as a cache's blocks and line-by-line writes never do) when the calendar
// reaches the earliest cycle it could arrive (its send cycle and the crossbar's latency), not
// when it is sent: so the crossbar, like everything shared, is booked in time order, and a
// requester running ahead of simulated time changes nothing shared but the calendar. If its
// links have room it is at its slice then and served at once; else it is queued again for the
// cycle it reaches the slice. Its data crosses back when its cycle is known. Crossbar links
// accept bookings in any order of their cycles, so neither direction delays a request by one
// dated later.
// An instance with no slices (a memory port: a hierarchy whose levels are all the units' own)
// holds no cache: it orders its requesters' requests and sends them to DRAM.
// One SC_METHOD, woken only at cycles that have requests or DRAM accesses to serve. With a
// lookahead of L cycles (every initiator dates its requests at least L cycles after the
// current simulated time: a unit's last level sends a miss after its tag check) it wakes at the
// cycle c of its earliest job and serves everything dated before c + L, so one wake-up serves
// L cycles of a busy hierarchy. Responses carry their data's cycle in their delay, so this
// changes no timing. A request sent while it serves (a unit's miss that waited for the MSHR a
// response freed) is dated no earlier than the job being served and is served in its turn.
#pragma once

#include <exception>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/multi_passthrough_target_socket.h>
#include <tlm_utils/simple_initiator_socket.h>

#include "model/mem/cache.h"
#include "model/mem/crossbar.h"
#include "model/mem/hierarchy.h"
#include "model/mem/mem_request.h"
#include "model/sc/clock.h"
#include "model/sched/event_queue.h"

namespace rtsim {

class SharedLevelsModule : public sc_core::sc_module, private ReadClient {
 public:
  // The TLM adapter's socket, which can tell how many initiators are bound to it (its size()
  // counts one when none is).
  struct InitiatorSocket
      : tlm_utils::multi_passthrough_target_socket<SharedLevelsModule, 32,
                                                   tlm::tlm_base_protocol_types, 0,
                                                   sc_core::SC_ZERO_OR_MORE_BOUND> {
    using multi_passthrough_target_socket::multi_passthrough_target_socket;
    uint32_t bound() const { return uint32_t(m_sockets.size()); }  // after elaboration
  };
  // TLM initiators bound here (none, or any number) take the first instance's crossbar ports
  // after the connected requesters'.
  InitiatorSocket in;
  tlm_utils::simple_initiator_socket_optional<SharedLevelsModule> out;  // unbound: connect_memory

  // One level's slices and crossbar, and the instance below it.
  struct Instance {
    std::string name;  // "l2", or "l1.g0" for the first instance of a group level
    uint32_t level = 0;
    uint32_t line_shift = 0;  // log2 of the level's line_bytes
    std::vector<std::unique_ptr<Cache>> slices;
    Crossbar crossbar;
    uint32_t below = kNoInstance;  // the next level's instance (kNoInstance: DRAM)
    uint32_t below_port = 0;       // this instance's port there
    // Per port: a unit's on_response (null function: the port is an instance above's).
    std::vector<std::function<void()>> ports;
    std::unique_ptr<MemoryTarget> memory;  // what its slices' misses and evictions go to
    CacheStats stats() const;              // summed over the slices
  };
  static constexpr uint32_t kNoInstance = ~0u;

  SC_HAS_PROCESS(SharedLevelsModule);
  // levels: the machine's whole hierarchy; the module builds the instances of its queued levels
  // (or one memory port when there are none) for `units` RT units. on_error receives what
  // serving a request threw (a failed DRAM access); without it the exception leaves the SystemC
  // kernel. lookahead: see above (0 for initiators that promise nothing); the first level's
  // crossbar latency adds to it. Throws std::invalid_argument for an impossible hierarchy.
  SharedLevelsModule(sc_core::sc_module_name name, const std::vector<MemoryLevelConfig>& levels,
                     uint32_t units, const Clock& clock, uint32_t lookahead = 0,
                     std::function<void(std::exception_ptr)> on_error = {});
  // A single shared level (tests, and outside models in front of a DRAM): levels = {config}.
  SharedLevelsModule(sc_core::sc_module_name name, const CacheConfig& config, const Clock& clock,
                     const SliceLayout& layout = {}, uint32_t lookahead = 0,
                     std::function<void(std::exception_ptr)> on_error = {});
  ~SharedLevelsModule() override;
  // Connects unit `unit`'s last own level as a requester of the first instance that serves it
  // (before the simulation); returns its port there. After each read's answer (its client's
  // read_done) on_response runs.
  uint32_t connect(uint32_t unit, std::function<void()> on_response);
  // The instance unit `unit`'s requests enter (its port's).
  uint32_t entry(uint32_t unit) const;
  // A read of `bytes` at `addr` sent from `port` of `instance` at cycle `at` (or now, if that is
  // later): its data's cycle is reported to client->read_done(token, ...), never during this
  // call.
  void read_request(uint32_t instance, uint32_t port, uint64_t addr, uint32_t bytes, Cycle at,
                    ReadClient* client, uint64_t token) {
    request(instance, port, RequestKind::Read, addr, bytes, at, Answer::Unit, client, token);
  }
  void write_request(uint32_t instance, uint32_t port, uint64_t addr, uint32_t bytes, Cycle at) {
    request(instance, port, RequestKind::Write, addr, bytes, at, Answer::Unit, nullptr, 0);
  }
  // A clean line the requester evicted, for a victim level (Cache::fill). Posted.
  void fill_request(uint32_t instance, uint32_t port, uint64_t addr, uint32_t bytes, Cycle at) {
    request(instance, port, RequestKind::Fill, addr, bytes, at, Answer::Unit, nullptr, 0);
  }
  const std::vector<Instance>& instances() const { return instances_; }
  const std::vector<MemoryLevelConfig>& levels() const { return levels_; }
  // The first and last index into instances() of level `level` (an index into levels()).
  std::pair<uint32_t, uint32_t> instances_of(uint32_t level) const;
  uint32_t slice_of(const Instance& instance, uint64_t addr) const;
  void track_cold_misses(uint64_t dense_begin = 0, uint64_t dense_end = 0);  // Cache's
  bool tracks_cold_misses() const;
  // Cache's, on every slice of level `level`'s instances (an index into levels()).
  void share_first_references(uint32_t level, double own_share, Cycle first_fetch_cycles);
  // Cache::warm on each line's slice of the first instance, now: accesses of RT units the
  // simulation does not drive.
  uint32_t warm(uint64_t addr, uint32_t bytes, bool write);
  size_t queued() const { return events_.size(); }  // requests and answers not yet served
  // A line per request record in use (at most `shown`, then a count): where it is (its
  // instance and slice, or the DRAM below it), what it is, where it comes from (unit, slot and
  // ray, asked of its requesters), what it waits for and since which cycle; oldest first.
  std::string waiting(size_t shown = 20) const;
  // Before the simulation starts: the memory bound to `out` speaks the approximately-timed
  // protocol and sends BEGIN_RESP at least `lead` cycles before the data's cycle.
  void use_timed_memory(uint32_t lead);
  // Before the simulation starts: the memory below is `memory`, by call (`out` stays unbound);
  // it answers every read later (kPending), at least `lead` cycles before its data's cycle.
  void connect_memory(MemoryTarget& memory, uint32_t lead);
  // Cycles ahead of simulated time its initiators date their requests, at the least.
  uint32_t lookahead() const { return lookahead_; }
  Cycle next_job() const { return events_.empty() ? kPending : events_.next_cycle(); }

 private:
  // Serve: the record's request at its instance (a lookup in its slice), or its access to the
  // DRAM; Reply: a read's answer to the level above at its data's cycle.
  enum class JobKind : uint8_t { Serve, Reply };
  struct Job {
    JobKind kind = JobKind::Serve;
    uint32_t request = 0;  // the record, in requests_
  };
  // A DRAM access in flight under the approximately-timed protocol: its record (a read's).
  struct BelowTransaction : tlm::tlm_generic_payload {
    uint32_t request = 0;
    bool read = false;
  };
  class Below;     // an instance's MemoryTarget
  class OutPort;   // `out` as the MemoryTarget below the last level
  friend OutPort;  // it sends through the module's socket

  void add_instances(uint32_t units);
  void end_of_elaboration() override;   // a module with no memory below is a wiring error
  void start_of_simulation() override;  // gives each crossbar a port per requester
  // A request from `port` of `instance` sent at `at`: a record that crosses to its slice and
  // joins the calendar.
  void request(uint32_t instance, uint32_t port, RequestKind kind, uint64_t addr, uint32_t bytes,
               Cycle at, Answer answer, ReadClient* client, uint64_t token,
               tlm::tlm_generic_payload* transaction = nullptr);
  uint32_t new_request(const MemRequest& r);
  void free_request(uint32_t request) {
    requests_[request].wait = RequestWait::Free;
    free_requests_.push_back(request);
  }
  tlm::tlm_sync_enum nb_transport_fw(int port, tlm::tlm_generic_payload& trans,
                                     tlm::tlm_phase& phase, sc_core::sc_time& delay);
  static MemRequest dram_request(uint32_t instance, uint64_t addr, uint32_t bytes, Cycle at);
  // Below an instance: a read (pending), a write or a fill at the next level or DRAM.
  void below_read(uint32_t instance, uint64_t addr, uint32_t bytes, Cycle at, ReadClient* client,
                  uint64_t token);
  void below_write(uint32_t instance, RequestKind kind, uint64_t addr, uint32_t bytes, Cycle at);
  // A read that waited below its slice (or its memory port) has its data at `ready`.
  void read_done(uint64_t request, Cycle ready, const ReadCharge& charge) override;
  ReadOrigin origin(uint64_t request) const override;

  void serve();
  void serve_window();  // every job dated before served_until_, in order, at this stamp
  // Asks the host's memory for the record of the miss the next job's answer completes (its
  // slice's set was asked for when the job joined): a hint given one job ahead, which changes
  // nothing modelled.
  void prime_next_job() const;
  void run_job(const Job& job, Cycle at);
  void access_dram(uint32_t request, Cycle at);
  // The read's answer, its data at `ready` at its slice: crosses back to its requester.
  [[gnu::always_inline]] void respond(uint32_t request, Cycle ready, const ReadCharge& charge);
  void add_job(const Job& job, Cycle at);
  // A transaction below of `bytes` at `addr` (the data is a scratch buffer: timing only).
  void prepare_below(tlm::tlm_generic_payload& t, tlm::tlm_command command, uint64_t addr,
                     uint32_t bytes);
  static std::runtime_error below_error(const tlm::tlm_generic_payload& t);
  Cycle send_below(tlm::tlm_command command, uint64_t addr, uint32_t bytes, Cycle at);
  // The approximately-timed form: a read's data comes back through nb_transport_bw.
  void send_timed(bool write, uint64_t addr, uint32_t bytes, Cycle at, uint64_t request);
  tlm::tlm_sync_enum nb_transport_bw(tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase,
                                     sc_core::sc_time& delay);
  void below_done(BelowTransaction& t, Cycle ready);  // a read's data at `ready`
  // A read below answered: its data at `ready`, a Reply job for its record.
  void reply_at(uint32_t request, Cycle ready);
  // What the DRAM answers: the read its token names.
  struct DramAnswers : ReadClient {
    explicit DramAnswers(SharedLevelsModule& m) : m(m) {}
    void read_done(uint64_t request, Cycle ready, const ReadCharge&) override {
      m.reply_at(uint32_t(request), ready);
    }
    SharedLevelsModule& m;
  };

  std::vector<MemoryLevelConfig> levels_;
  uint32_t units_;             // RT units the module serves
  uint32_t first_queued_ = 0;  // the index in levels_ of the first level this module holds
  std::vector<Instance> instances_;
  Clock clock_;
  uint32_t lookahead_;  // at least 1: the initiators' promise
  uint32_t window_;     // a wake-up at cycle c serves what is dated before c + it (<= lookahead_)
  std::unique_ptr<OutPort> out_port_;  // `out` as a MemoryTarget
  MemoryTarget* memory_;               // the memory below the last level: out_port_ or by call
  DramAnswers dram_answers_{*this};
  std::vector<std::unique_ptr<BelowTransaction>> below_pool_;
  std::vector<BelowTransaction*> below_free_;
  std::function<void(std::exception_ptr)> on_error_;
  Calendar<Job> events_;              // the jobs at their cycles
  std::vector<MemRequest> requests_;  // the records, reused through free_requests_
  std::vector<uint32_t> free_requests_;
  sc_core::sc_event wake_;
  Cycle armed_ = kPending;  // the cycle wake_ is notified for (kPending: none)
  Cycle served_until_ = 0;  // every job dated before it has been served
  sc_core::sc_time stamp_;  // the simulated time serve() runs at
  bool serving_ = false;    // serve() arms wake_ for the next job when it ends
  tlm::tlm_generic_payload below_trans_;
  std::vector<unsigned char> scratch_;
};

}  // namespace rtsim
