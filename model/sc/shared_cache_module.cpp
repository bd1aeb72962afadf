#include "model/sc/shared_cache_module.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "model/mem/slice_hash.h"

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
  crossbar_.add_units(uint32_t(in.size()));
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

void SharedCacheModule::share_first_references(double own_share) {
  for (auto& slice : slices_) slice->share_first_references(own_share);
}

void SharedCacheModule::use_timed_memory(uint32_t lead) {
  timed_below_ = true;
  window_ = std::min(lead + 1, lookahead_);
}

void SharedCacheModule::add_job(const Job& job, Cycle at) {
  uint32_t id;
  if (free_jobs_.empty()) {
    id = uint32_t(jobs_.size());
    jobs_.push_back(job);
  } else {
    id = free_jobs_.back();
    free_jobs_.pop_back();
    jobs_[id] = job;
  }
  events_.push(at, id);
  if (serving_ || at >= armed_) return;  // serve() arms wake_, or an earlier wake is pending
  armed_ = at;
  wake_.notify(clock_.delay_to(at));
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
  Job job;
  job.kind = write ? JobKind::Write : JobKind::Read;
  job.port = port;
  job.slice = slice_of(trans.get_address());
  job.trans = write ? nullptr : &trans;
  // Looked up now, while the initiator's transaction is in the host's cache.
  job.charge_out = write ? nullptr : trans.get_extension<ReadChargeExtension>();
  job.addr = trans.get_address();
  job.bytes = trans.get_data_length();
  Cycle sent = clock_.cycles(sim_now() + delay);
  Cycle at = crossbar_.to_slice(uint32_t(port), job.slice, sent,
                                write ? job.bytes : Crossbar::kRequestBytes);
  // During serve() an L1 may send a miss that waited for an MSHR freed by a response: dated at
  // or after the job being served, it joins the calendar in order. From outside, a request
  // dated inside the window already served breaks the initiators' promise.
  if (!serving_ && at < served_until_)
    throw std::logic_error(std::string(name()) + ": a request dated cycle " + std::to_string(at) +
                           " came after cycle " + std::to_string(served_until_) +
                           " was served: its initiator breaks the lookahead of " +
                           std::to_string(lookahead_) + " cycles");
  add_job(job, at);
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
    EventQueue::Event e;
    while (events_.pop_before(served_until_, e)) run_job(e.item, e.cycle);
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

void SharedCacheModule::run_job(uint32_t id, Cycle at) {
  const Job& job = jobs_[id];  // read before anything that may add jobs (and move jobs_)
  switch (job.kind) {
    case JobKind::Read: {
      ReadCharge charge;
      Cache& slice = *slices_[job.slice];
      Cycle ready = slice.read(job.addr, job.bytes, at, this, id, charge);
      jobs_[id].charge += charge;
      if (ready != kPending) respond(id, ready);
      return;
    }
    case JobKind::Write:
      free_jobs_.push_back(id);
      slices_[job.slice]->write(job.addr, job.bytes, at);
      return;
    case JobKind::DramRead: {
      free_jobs_.push_back(id);
      if (timed_below_) return send_timed(job, at);
      ReadClient* client = job.client;
      uint64_t token = job.token;
      Cycle ready = send_below(tlm::TLM_READ_COMMAND, job.addr, job.bytes, at);
      client->read_done(token, ready, {});
      return;
    }
    case JobKind::DramWrite:
      free_jobs_.push_back(id);
      if (timed_below_) return send_timed(job, at);
      send_below(tlm::TLM_WRITE_COMMAND, job.addr, job.bytes, at);
      return;
    case JobKind::DramDone: {
      free_jobs_.push_back(id);
      ReadClient* client = job.client;
      uint64_t token = job.token;
      client->read_done(token, at, {});
      return;
    }
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

void SharedCacheModule::read_done(uint64_t job, Cycle ready, const ReadCharge& charge) {
  jobs_[job].charge += charge;
  respond(uint32_t(job), ready);
}

void SharedCacheModule::respond(uint32_t id, Cycle ready) {
  const Job& job = jobs_[id];
  tlm::tlm_generic_payload& trans = *job.trans;
  int port = job.port;
  if (job.charge_out) job.charge_out->charge = job.charge;
  trans.set_response_status(tlm::TLM_OK_RESPONSE);
  Cycle arrived = crossbar_.to_unit(job.slice, uint32_t(port), ready, job.bytes);
  free_jobs_.push_back(id);  // the response below may add jobs
  tlm::tlm_phase phase = tlm::BEGIN_RESP;
  sc_core::sc_time delay = clock_.time(arrived) - stamp_;  // serve() runs at stamp_
  in[port]->nb_transport_bw(trans, phase, delay);
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
  if (!t.client) return;  // a write's response
  Job job;
  job.kind = JobKind::DramDone;
  job.client = t.client;
  job.token = t.token;
  // Outside serve(), a response dated inside the window already served (a memory that answers
  // with less lead than the window) is served now, in order with what it starts there.
  bool late = !serving_ && ready < served_until_;
  add_job(job, ready);
  if (late) serve_window();
}

}  // namespace rtsim
