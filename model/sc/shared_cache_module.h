// The shared L2 as an sc_module that serves its requests in simulated-time order: the crossbar
// from the RT units' L1s (model/mem/crossbar.h) and the L2's address-hashed slices behind it.
// Requests come by function call from connected requesters (the RT units' L1s,
// model/sc/tlm_memory.h: connect) or as TLM-2.0 approximately-timed transactions from initiators
// bound to `in` (an adapter for outside models): BEGIN_REQ dated by its delay, answered END_REQ
// at once (the request queue has no bound). Either way a request becomes one small record (a
// Job) in the module's calendar. The answer to a read is sent as soon as the data's cycle is
// known (a hit: when the request is served; a miss: when the DRAM has answered), dated by the
// data's cycle: its client's read_done for a connected requester, BEGIN_RESP with a delay for
// a TLM initiator. Writes are posted (a TLM write completes on the request).
// Why a queue: units run up to a quantum ahead of simulated time and an L1 miss that waited for
// an MSHR leaves later than it was made, so requests arrive out of time order. The module
// holds them in an event calendar and serves each at its own cycle, when simulated time
// reaches it; the cache (model/mem/cache.h) and the DRAM below therefore see every request in
// non-decreasing cycle order, and a request dated earlier is never delayed by one dated later.
// The DRAM is reached at the request's own cycle, by call or through `out`. By call
// (connect_memory): the banked DRAM (model/sc/banked_dram_module.h) as a QueuedMemory, which
// reports each read's data cycle at least `lead` cycles before it. Through `out`, in one of two
// protocols: by default the base protocol's blocking transport (loosely timed), so any
// loosely-timed TLM memory can be bound there; after use_timed_memory(lead), the approximately-
// timed one (a DRAMSys-class model): BEGIN_REQ through nb_transport_fw, and the data's cycle in
// the delay of BEGIN_RESP, sent at least `lead` cycles before it (0: at that cycle). With a
// lead the module serves at most lead + 1 cycles ahead, so an answer is never dated before a
// job already served; one dated inside the window already served is served at once, with what
// it starts there, in cycle order.
// A request crosses the crossbar to its slice (slice_of: a hash of the line address; a request
// must not span lines, as an L1's blocks and line-by-line writes never do) when it
// arrives, and is queued for the cycle it reaches the slice; its data crosses back when its
// cycle is known. Crossbar links accept bookings in any order of their cycles, so neither
// direction delays a request by one dated later.
// One SC_METHOD, woken only at cycles that have requests or DRAM accesses to serve. With a
// lookahead of L cycles (every initiator dates its requests at least L cycles after the
// current simulated time: an L1 sends a miss after its tag check) it wakes at the cycle c of
// its earliest job and serves everything dated before c + L, so one wake-up serves L cycles
// of a busy L2. Responses carry their data's cycle in their delay, so this changes no timing.
// A request sent while it serves (an L1 miss that waited for the MSHR a response freed) is dated
// no earlier than the job being served and is served in its turn.
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
#include "model/sc/clock.h"
#include "model/sc/tlm_memory.h"
#include "model/sched/event_queue.h"

namespace rtsim {

class SharedCacheModule : public sc_core::sc_module, private MemoryTarget, private ReadClient {
 public:
  // The TLM adapter's socket, which can tell how many initiators are bound to it (its size()
  // counts one when none is).
  struct InitiatorSocket
      : tlm_utils::multi_passthrough_target_socket<SharedCacheModule, 32,
                                                   tlm::tlm_base_protocol_types, 0,
                                                   sc_core::SC_ZERO_OR_MORE_BOUND> {
    using multi_passthrough_target_socket::multi_passthrough_target_socket;
    uint32_t bound() const { return uint32_t(m_sockets.size()); }  // after elaboration
  };
  // TLM initiators bound here (none, or any number) take the crossbar ports after the connected
  // requesters'.
  InitiatorSocket in;
  tlm_utils::simple_initiator_socket_optional<SharedCacheModule> out;  // unbound: connect_memory

  SC_HAS_PROCESS(SharedCacheModule);
  // on_error receives what serving a request threw (a failed DRAM access); without it the
  // exception leaves the SystemC kernel.
  // lookahead: see above (0 for initiators that promise nothing); the crossbar's latency adds
  // to it. Throws std::invalid_argument for an impossible config or layout.
  SharedCacheModule(sc_core::sc_module_name name, const CacheConfig& config, const Clock& clock,
                    const L2Layout& layout = {}, uint32_t lookahead = 0,
                    std::function<void(std::exception_ptr)> on_error = {});
  // Connects a requester that calls read_request and write_request (before the simulation);
  // returns its port. After each read's answer (its client's read_done) on_response runs.
  uint32_t connect(std::function<void()> on_response);
  // A read of `bytes` at `addr` sent from `port` at cycle `at` (or now, if that is later): its
  // data's cycle is reported to client->read_done(token, ...), never during this call.
  void read_request(uint32_t port, uint64_t addr, uint32_t bytes, Cycle at, ReadClient* client,
                    uint64_t token) {
    request(port, JobKind::Read, addr, bytes, at, client, token);
  }
  void write_request(uint32_t port, uint64_t addr, uint32_t bytes, Cycle at) {
    request(port, JobKind::Write, addr, bytes, at, nullptr, 0);
  }
  uint32_t slice_count() const { return uint32_t(slices_.size()); }
  const Cache& slice(uint32_t i) const { return *slices_[i]; }
  uint32_t slice_of(uint64_t addr) const;
  CacheStats stats() const;  // summed over the slices
  const Crossbar& crossbar() const { return crossbar_; }
  void track_cold_misses(uint64_t dense_begin = 0, uint64_t dense_end = 0);  // Cache's
  bool tracks_cold_misses() const { return slices_[0]->tracks_cold_misses(); }
  void share_first_references(double own_share, Cycle first_fetch_cycles);  // Cache's
  // Cache::warm on each line's slice, now: accesses of RT units the simulation does not drive.
  uint32_t warm(uint64_t addr, uint32_t bytes, bool write);
  size_t queued() const { return events_.size(); }  // requests and DRAM reads not yet served
  // Before the simulation starts: the memory bound to `out` speaks the approximately-timed
  // protocol and sends BEGIN_RESP at least `lead` cycles before the data's cycle.
  void use_timed_memory(uint32_t lead);
  // Before the simulation starts: the memory below is `memory`, by call (`out` stays unbound);
  // it answers reads at least `lead` cycles before their data's cycle.
  void connect_memory(QueuedMemory& memory, uint32_t lead);
  // Cycles ahead of simulated time its initiators date their requests, at the least.
  uint32_t lookahead() const { return lookahead_; }
  Cycle next_job() const { return events_.empty() ? kPending : events_.next_cycle(); }

 private:
  enum class JobKind : uint8_t { Read, Write, DramRead, DramWrite, DramDone };
  // A DRAM access in flight under the approximately-timed protocol (DramRead: its reader).
  struct BelowTransaction : tlm::tlm_generic_payload {
    ReadClient* client = nullptr;
    uint64_t token = 0;
  };
  // One request record, kept in the calendar itself. Read: who waits (a connected requester's
  // client and token; from a TLM initiator, its transaction as the token); DramRead: the slice's
  // miss.
  struct Job {
    JobKind kind = JobKind::Read;
    uint32_t port = 0;
    uint32_t slice = 0;
    uint32_t bytes = 0;
    uint64_t addr = 0;
    ReadClient* client = nullptr;
    uint64_t token = 0;
  };
  // A read that missed in its slice, until the slice reports its data: its record, and what it
  // has cost so far.
  struct MissedRead {
    Job job;
    ReadCharge charge;
  };

  void end_of_elaboration() override;   // a module with no memory below is a wiring error
  void start_of_simulation() override;  // gives the crossbar a port per requester
  // A request from `port` sent at `at`: crosses to its slice and joins the calendar.
  void request(uint32_t port, JobKind kind, uint64_t addr, uint32_t bytes, Cycle at,
               ReadClient* client, uint64_t token);
  tlm::tlm_sync_enum nb_transport_fw(int port, tlm::tlm_generic_payload& trans,
                                     tlm::tlm_phase& phase, sc_core::sc_time& delay);
  // Below the cache: its misses and writes become DRAM accesses at their own cycle.
  Cycle read(uint64_t addr, uint32_t bytes, Cycle at, ReadClient* client, uint64_t token,
             ReadCharge& charge) override;
  void write(uint64_t addr, uint32_t bytes, Cycle at) override;
  void read_done(uint64_t missed, Cycle ready, const ReadCharge& charge) override;

  void serve();
  void serve_window();  // every job dated before served_until_, in order, at this stamp
  // Asks the host's memory for the record of the miss the next job's answer completes (its
  // slice's set was asked for when the job joined): a hint given one job ahead, which changes
  // nothing modelled.
  void prime_next_job() const;
  void run_job(const Job& job, Cycle at);
  [[gnu::always_inline]] void respond(const Job& job, Cycle ready, const ReadCharge& charge);
  void add_job(const Job& job, Cycle at);
  // A transaction below of `bytes` at `addr` (the data is a scratch buffer: timing only).
  void prepare_below(tlm::tlm_generic_payload& t, tlm::tlm_command command, uint64_t addr,
                     uint32_t bytes);
  static std::runtime_error below_error(const tlm::tlm_generic_payload& t);
  Cycle send_below(tlm::tlm_command command, uint64_t addr, uint32_t bytes, Cycle at);
  // The approximately-timed form: a read's data comes back through nb_transport_bw.
  void send_timed(const Job& job, Cycle at);
  tlm::tlm_sync_enum nb_transport_bw(tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase,
                                     sc_core::sc_time& delay);
  void below_done(BelowTransaction& t, Cycle ready);  // a read's data at `ready`
  // A read's data from below at `ready`, for `client` (a slice) and its token: a DramDone job.
  void answer_below(ReadClient* client, uint64_t token, Cycle ready);
  // What a QueuedMemory below answers: the pending read (below_reads_) its token names.
  struct MemoryAnswers : ReadClient {
    explicit MemoryAnswers(SharedCacheModule& l2) : l2(l2) {}
    void read_done(uint64_t read, Cycle ready, const ReadCharge&) override;
    SharedCacheModule& l2;
  };
  struct BelowRead {
    ReadClient* client;
    uint64_t token;
  };

  Clock clock_;
  uint32_t lookahead_;  // at least 1: the initiators' promise
  uint32_t window_;     // a wake-up at cycle c serves what is dated before c + it (<= lookahead_)
  bool timed_below_ = false;
  QueuedMemory* memory_ = nullptr;  // the memory below, by call (else `out`)
  MemoryAnswers answers_{*this};
  std::vector<BelowRead> below_reads_;
  std::vector<uint32_t> free_below_reads_;
  std::vector<std::unique_ptr<BelowTransaction>> below_pool_;
  std::vector<BelowTransaction*> below_free_;
  std::function<void(std::exception_ptr)> on_error_;
  std::vector<std::function<void()>> connected_;  // per connected port: its on_response
  std::vector<std::unique_ptr<Cache>> slices_;
  uint32_t line_shift_ = 0;
  Crossbar crossbar_;
  Calendar<Job> events_;  // the jobs at their cycles
  std::vector<MissedRead> missed_;
  std::vector<uint32_t> free_missed_;
  sc_core::sc_event wake_;
  Cycle armed_ = kPending;  // the cycle wake_ is notified for (kPending: none)
  Cycle served_until_ = 0;  // every job dated before it has been served
  sc_core::sc_time stamp_;  // the simulated time serve() runs at
  bool serving_ = false;    // serve() arms wake_ for the next job when it ends
  tlm::tlm_generic_payload below_trans_;
  std::vector<unsigned char> scratch_;
};

}  // namespace rtsim
