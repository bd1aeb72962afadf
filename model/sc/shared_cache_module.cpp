#include "model/sc/shared_cache_module.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "model/mem/slice_hash.h"
#include "model/mem/slot_pool.h"

namespace rtsim {

namespace {

CacheConfig slice_config(const CacheConfig& config, uint32_t slices) {
  CacheConfig c = config;
  c.size_bytes = config.size_bytes / std::max<uint32_t>(slices, 1);
  return c;
}

}  // namespace

SharedCacheModule::SharedCacheModule(sc_core::sc_module_name name, const CacheConfig& config,
                                     const Clock& clock, const L2Layout& layout, uint32_t lookahead,
                                     std::function<void(std::exception_ptr)> on_error)
    : sc_module(name),
      in("in"),
      out("out"),
      clock_(clock),
      lookahead_(std::max<uint32_t>(lookahead + layout.crossbar.latency, 1)),
      window_(lookahead_),
      on_error_(std::move(on_error)),
      crossbar_(layout.crossbar, layout.slices) {
  std::string problem = l2_layout_problem(config, layout);
  if (!problem.empty()) throw std::invalid_argument(problem);
  MemoryTarget* below = this;
  for (uint32_t i = 0; i < layout.slices; ++i)
    slices_.push_back(
        std::make_unique<Cache>(slice_config(config, layout.slices), below, CacheRole::L2));
  line_shift_ = uint32_t(__builtin_ctz(config.line_bytes));
  in.register_nb_transport_fw(this, &SharedCacheModule::nb_transport_fw);
  out.register_nb_transport_bw(this, &SharedCacheModule::nb_transport_bw);
  SC_METHOD(serve);
  sensitive << wake_;
  dont_initialize();
}

void SharedCacheModule::end_of_elaboration() {
  if (!memory_ && out.size() == 0)
    throw std::logic_error(std::string(name()) + ": no memory below (bind out or connect one)");
}

// After every socket has completed its binding at the end of elaboration.
void SharedCacheModule::start_of_simulation() {
  crossbar_.add_units(uint32_t(connected_.size()) + in.bound());
}

uint32_t SharedCacheModule::connect(std::function<void()> on_response) {
  connected_.push_back(std::move(on_response));
  return uint32_t(connected_.size() - 1);
}

uint32_t SharedCacheModule::slice_of(uint64_t addr) const {
  return slice_of_line(addr >> line_shift_, uint32_t(slices_.size()));
}

uint32_t SharedCacheModule::warm(uint64_t addr, uint32_t bytes, bool write) {
  Cycle now = clock_.cycles(sim_now());
  uint64_t line_bytes = uint64_t(1) << line_shift_;
  uint32_t fetched = 0;
  for (uint64_t at = addr, end = addr + std::max<uint32_t>(bytes, 1); at < end;) {
    uint64_t stop = std::min(end, (at | (line_bytes - 1)) + 1);
    fetched += slices_[slice_of(at)]->warm(at, uint32_t(stop - at), now, write);
    at = stop;
  }
  return fetched;
}

CacheStats SharedCacheModule::stats() const {
  CacheStats sum;
  for (const auto& slice : slices_) sum += slice->stats();
  return sum;
}

void SharedCacheModule::track_cold_misses(uint64_t dense_begin, uint64_t dense_end) {
  for (auto& slice : slices_) slice->track_cold_misses(dense_begin, dense_end);
}

void SharedCacheModule::share_first_references(double own_share, Cycle first_fetch_cycles) {
  for (auto& slice : slices_) slice->share_first_references(own_share, first_fetch_cycles);
}

void SharedCacheModule::use_timed_memory(uint32_t lead) {
  timed_below_ = true;
  window_ = std::min(lead + 1, lookahead_);
}

void SharedCacheModule::connect_memory(QueuedMemory& memory, uint32_t lead) {
  memory_ = &memory;
  memory.answer_to(answers_);
  use_timed_memory(lead);
}

void SharedCacheModule::add_job(const Job& job, Cycle at) {
  events_.push(at, job);
  if (serving_ || at >= armed_) return;  // serve() arms wake_, or an earlier wake is pending
  armed_ = at;
  wake_.notify(clock_.delay_to(at));
}

void SharedCacheModule::request(uint32_t port, JobKind kind, uint64_t addr, uint32_t bytes,
                                Cycle at, ReadClient* client, uint64_t token) {
  bool write = kind == JobKind::Write;
  Job job;
  job.kind = kind;
  job.port = port;
  job.slice = slice_of(addr);
  job.addr = addr;
  job.bytes = bytes;
  job.client = client;
  job.token = token;
  Cycle sent = std::max(at, clock_.cycles(sim_now()));
  Cycle arrives =
      crossbar_.to_slice(port, job.slice, sent, write ? bytes : Crossbar::kRequestBytes);
  // During serve() an L1 may send a miss that waited for an MSHR freed by a response: dated at
  // or after the job being served, it joins the calendar in order. From outside, a request
  // dated inside the window already served breaks the requesters' promise.
  if (!serving_ && arrives < served_until_)
    throw std::logic_error(std::string(name()) + ": a request dated cycle " +
                           std::to_string(arrives) + " came after cycle " +
                           std::to_string(served_until_) +
                           " was served: its requester breaks the lookahead of " +
                           std::to_string(lookahead_) + " cycles");
  slices_[job.slice]->prime(addr);
  add_job(job, arrives);
}

tlm::tlm_sync_enum SharedCacheModule::nb_transport_fw(int port, tlm::tlm_generic_payload& trans,
                                                      tlm::tlm_phase& phase,
                                                      sc_core::sc_time& delay) {
  if (phase != tlm::BEGIN_REQ) return tlm::TLM_COMPLETED;  // END_RESP: nothing left to do
  bool write = trans.get_command() == tlm::TLM_WRITE_COMMAND;
  if (!write && trans.get_command() != tlm::TLM_READ_COMMAND) {
    trans.set_response_status(tlm::TLM_COMMAND_ERROR_RESPONSE);
    return tlm::TLM_COMPLETED;
  }
  request(uint32_t(connected_.size() + port), write ? JobKind::Write : JobKind::Read,
          trans.get_address(), trans.get_data_length(), clock_.cycles(sim_now() + delay), nullptr,
          reinterpret_cast<uint64_t>(&trans));
  if (write) {
    trans.set_response_status(tlm::TLM_OK_RESPONSE);
    return tlm::TLM_COMPLETED;
  }
  phase = tlm::END_REQ;
  return tlm::TLM_UPDATED;
}

void SharedCacheModule::serve() {
  served_until_ = clock_.cycles(sim_now()) + window_;
  armed_ = kPending;
  serve_window();
}

void SharedCacheModule::serve_window() {
  try {
    stamp_ = sim_now();
    serving_ = true;
    Calendar<Job>::Event e;
    while (events_.pop_before(served_until_, e)) {
      prime_next_job();
      run_job(e.item, e.cycle);
    }
    serving_ = false;
    if (!events_.empty() && events_.next_cycle() < armed_) {  // wake for the next job
      armed_ = events_.next_cycle();
      wake_.notify(clock_.delay_to(armed_));
    }
  } catch (...) {
    serving_ = false;
    if (!on_error_) throw;
    on_error_(std::current_exception());
  }
}

void SharedCacheModule::prime_next_job() const {
  Job next;
  if (!events_.peek(next)) return;
  bool answers = next.kind == JobKind::Read || next.kind == JobKind::DramDone;
  if (answers && next.client) next.client->prime_done(next.token);
}

void SharedCacheModule::run_job(const Job& job, Cycle at) {
  switch (job.kind) {
    case JobKind::Read: {
      // The slice reports a miss's data later (never during the read) under the id of the
      // record it then takes (nothing takes one during the read).
      uint32_t id = next_slot(missed_, free_missed_);
      ReadCharge charge;
      Cycle ready = slices_[job.slice]->read(job.addr, job.bytes, at, this, id, charge);
      if (ready != kPending) return respond(job, ready, charge);
      missed_[take_slot(missed_, free_missed_)] = {job, charge};
      return;
    }
    case JobKind::Write: return slices_[job.slice]->write(job.addr, job.bytes, at);
    case JobKind::DramRead: {
      if (memory_) {
        uint32_t read = take_slot(below_reads_, free_below_reads_);
        below_reads_[read] = {job.client, job.token};
        return memory_->request(job.addr, job.bytes, false, at, read);
      }
      if (timed_below_) return send_timed(job, at);
      Cycle ready = send_below(tlm::TLM_READ_COMMAND, job.addr, job.bytes, at);
      return job.client->read_done(job.token, ready, {});
    }
    case JobKind::DramWrite:
      if (memory_) return memory_->request(job.addr, job.bytes, true, at, 0);
      if (timed_below_) return send_timed(job, at);
      send_below(tlm::TLM_WRITE_COMMAND, job.addr, job.bytes, at);
      return;
    case JobKind::DramDone: return job.client->read_done(job.token, at, {});
  }
}

Cycle SharedCacheModule::read(uint64_t addr, uint32_t bytes, Cycle at, ReadClient* client,
                              uint64_t token, ReadCharge&) {
  Job job;
  job.kind = JobKind::DramRead;
  job.addr = addr;
  job.bytes = bytes;
  job.client = client;
  job.token = token;
  add_job(job, at);
  return kPending;
}

void SharedCacheModule::write(uint64_t addr, uint32_t bytes, Cycle at) {
  Job job;
  job.kind = JobKind::DramWrite;
  job.addr = addr;
  job.bytes = bytes;
  add_job(job, at);
}

void SharedCacheModule::read_done(uint64_t missed, Cycle ready, const ReadCharge& charge) {
  MissedRead m = missed_[missed];
  free_missed_.push_back(uint32_t(missed));  // the answer may add jobs
  m.charge += charge;
  respond(m.job, ready, m.charge);
}

inline void SharedCacheModule::respond(const Job& job, Cycle ready, const ReadCharge& charge) {
  Cycle arrived = crossbar_.to_unit(job.slice, job.port, ready, job.bytes);
  if (job.port < connected_.size()) {
    job.client->read_done(job.token, arrived, charge);
    connected_[job.port]();
    return;
  }
  auto& trans = *reinterpret_cast<tlm::tlm_generic_payload*>(job.token);
  trans.set_response_status(tlm::TLM_OK_RESPONSE);
  tlm::tlm_phase phase = tlm::BEGIN_RESP;
  sc_core::sc_time delay = clock_.time(arrived) - stamp_;  // serve() runs at stamp_
  in[int(job.port - connected_.size())]->nb_transport_bw(trans, phase, delay);
}

void SharedCacheModule::prepare_below(tlm::tlm_generic_payload& t, tlm::tlm_command command,
                                      uint64_t addr, uint32_t bytes) {
  if (scratch_.size() < bytes) scratch_.resize(bytes);
  t.set_command(command);
  t.set_address(addr);
  t.set_data_ptr(scratch_.data());
  t.set_data_length(bytes);
  t.set_streaming_width(bytes);
  t.set_byte_enable_ptr(nullptr);
  t.set_dmi_allowed(false);
  t.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
}

std::runtime_error SharedCacheModule::below_error(const tlm::tlm_generic_payload& t) {
  return std::runtime_error("memory access at " + std::to_string(t.get_address()) +
                            " failed: " + t.get_response_string());
}

Cycle SharedCacheModule::send_below(tlm::tlm_command command, uint64_t addr, uint32_t bytes,
                                    Cycle at) {
  tlm::tlm_generic_payload& t = below_trans_;
  prepare_below(t, command, addr, bytes);
  sc_core::sc_time delay = clock_.time(at) - stamp_;
  out->b_transport(t, delay);
  if (t.is_response_error()) throw below_error(t);
  return clock_.cycles(stamp_ + delay);
}

void SharedCacheModule::send_timed(const Job& job, Cycle at) {
  if (below_free_.empty()) {
    below_pool_.push_back(std::make_unique<BelowTransaction>());
    below_free_.push_back(below_pool_.back().get());
  }
  BelowTransaction& t = *below_free_.back();
  below_free_.pop_back();
  bool write = job.kind == JobKind::DramWrite;
  prepare_below(t, write ? tlm::TLM_WRITE_COMMAND : tlm::TLM_READ_COMMAND, job.addr, job.bytes);
  t.client = write ? nullptr : job.client;
  t.token = job.token;
  tlm::tlm_phase phase = tlm::BEGIN_REQ;
  sc_core::sc_time delay = clock_.time(at) - stamp_;
  tlm::tlm_sync_enum status = out->nb_transport_fw(t, phase, delay);
  if (status == tlm::TLM_COMPLETED || phase == tlm::BEGIN_RESP) {
    if (t.is_response_error()) throw below_error(t);
    below_done(t, std::max(at, clock_.cycles(stamp_ + delay)));
  }
}

tlm::tlm_sync_enum SharedCacheModule::nb_transport_bw(tlm::tlm_generic_payload& trans,
                                                      tlm::tlm_phase& phase,
                                                      sc_core::sc_time& delay) {
  if (phase != tlm::BEGIN_RESP) return tlm::TLM_ACCEPTED;  // END_REQ
  auto& t = static_cast<BelowTransaction&>(trans);
  if (t.is_response_error()) {
    if (!on_error_) throw below_error(t);
    on_error_(std::make_exception_ptr(below_error(t)));
    return tlm::TLM_COMPLETED;
  }
  below_done(t, clock_.cycles(sim_now() + delay));
  return tlm::TLM_COMPLETED;
}

void SharedCacheModule::below_done(BelowTransaction& t, Cycle ready) {
  below_free_.push_back(&t);
  if (t.client) answer_below(t.client, t.token, ready);  // else a write's response
}

void SharedCacheModule::MemoryAnswers::read_done(uint64_t read, Cycle ready, const ReadCharge&) {
  BelowRead r = l2.below_reads_[read];
  l2.free_below_reads_.push_back(uint32_t(read));
  l2.answer_below(r.client, r.token, ready);
}

void SharedCacheModule::answer_below(ReadClient* client, uint64_t token, Cycle ready) {
  Job job;
  job.kind = JobKind::DramDone;
  job.client = client;
  job.token = token;
  // Outside serve(), a response dated inside the window already served (a memory that answers
  // with less lead than the window) is served now, in order with what it starts there.
  bool late = !serving_ && ready < served_until_;
  add_job(job, ready);
  if (late) serve_window();
}

}  // namespace rtsim
