#include "model/sc/shared_levels_module.h"

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

// The levels of the single-level form: the units' own level (not built here) joined by the
// layout's crossbar to `config`, shared.
std::vector<MemoryLevelConfig> one_shared_level(const CacheConfig& config,
                                                const SliceLayout& layout) {
  MemoryLevelConfig own, shared;
  own.name = "l1";
  own.link = layout.crossbar;
  shared.name = "l2";
  shared.scope = LevelScope::Shared;
  shared.cache = config;
  shared.slices = layout.slices;
  return {own, shared};
}

}  // namespace

// What an instance's slices see below them: the next level's instance, or the DRAM.
class SharedLevelsModule::Below : public MemoryTarget {
 public:
  Below(SharedLevelsModule& module, uint32_t instance) : module_(module), instance_(instance) {}
  Cycle read(uint64_t addr, uint32_t bytes, Cycle at, ReadClient* client, uint64_t token,
             ReadCharge&) override {
    module_.below_read(instance_, addr, bytes, at, client, token);
    return kPending;
  }
  void write(uint64_t addr, uint32_t bytes, Cycle at) override {
    module_.below_write(instance_, JobKind::Write, addr, bytes, at);
  }
  void fill(uint64_t addr, uint32_t bytes, Cycle at) override {
    module_.below_write(instance_, JobKind::Fill, addr, bytes, at);
  }

 private:
  SharedLevelsModule& module_;
  uint32_t instance_;
};

CacheStats SharedLevelsModule::Instance::stats() const {
  CacheStats sum;
  for (const auto& slice : slices) sum += slice->stats();
  return sum;
}

SharedLevelsModule::SharedLevelsModule(sc_core::sc_module_name name,
                                       const std::vector<MemoryLevelConfig>& levels, uint32_t units,
                                       const Clock& clock, uint32_t lookahead,
                                       std::function<void(std::exception_ptr)> on_error)
    : sc_module(name),
      in("in"),
      out("out"),
      levels_(levels),
      units_(units),
      clock_(clock),
      on_error_(std::move(on_error)) {
  first_queued_ = own_levels(levels_);
  uint32_t link = first_queued_ > 0 ? levels_[first_queued_ - 1].link.latency : 0;
  lookahead_ = window_ = std::max<uint32_t>(lookahead + link, 1);
  add_instances(units);
  in.register_nb_transport_fw(this, &SharedLevelsModule::nb_transport_fw);
  out.register_nb_transport_bw(this, &SharedLevelsModule::nb_transport_bw);
  SC_METHOD(serve);
  sensitive << wake_;
  dont_initialize();
}

SharedLevelsModule::SharedLevelsModule(sc_core::sc_module_name name, const CacheConfig& config,
                                       const Clock& clock, const SliceLayout& layout,
                                       uint32_t lookahead,
                                       std::function<void(std::exception_ptr)> on_error)
    : SharedLevelsModule(name, one_shared_level(config, layout), 1, clock, lookahead,
                         std::move(on_error)) {}

void SharedLevelsModule::add_instances(uint32_t units) {
  // The first instance of each level this module holds, in level order; a memory port alone
  // when the units' own levels are the whole hierarchy.
  std::vector<uint32_t> first(levels_.size() + 1, 0);
  uint32_t count = 0;
  for (uint32_t i = first_queued_; i < levels_.size(); ++i) {
    first[i] = count;
    count += level_instances(levels_[i], units);
  }
  first[levels_.size()] = count;
  instances_.reserve(std::max<uint32_t>(count, 1));
  if (count == 0) {
    Instance port{"memory_port",
                  uint32_t(levels_.size()),
                  0,
                  {},
                  Crossbar({}, 0),
                  kNoInstance,
                  0,
                  {},
                  std::make_unique<Below>(*this, 0)};
    instances_.push_back(std::move(port));
    return;
  }
  for (uint32_t i = first_queued_; i < levels_.size(); ++i) {
    const MemoryLevelConfig& level = levels_[i];
    std::string problem = slice_layout_problem(level.cache, {level.slices, levels_[i - 1].link});
    if (!problem.empty()) throw std::invalid_argument(level.name + ": " + problem);
    uint32_t per = units_per_instance(level, units);
    uint32_t n = first[i + 1] - first[i];
    for (uint32_t k = 0; k < n; ++k) {
      uint32_t index = uint32_t(instances_.size());
      Instance inst{n > 1 ? level.name + ".g" + std::to_string(k) : level.name,
                    i,
                    uint32_t(__builtin_ctz(level.cache.line_bytes)),
                    {},
                    Crossbar(levels_[i - 1].link, level.slices),
                    kNoInstance,
                    0,
                    {},
                    std::make_unique<Below>(*this, index)};
      for (uint32_t s = 0; s < level.slices; ++s)
        inst.slices.push_back(std::make_unique<Cache>(slice_config(level.cache, level.slices),
                                                      inst.memory.get(), cache_place(levels_, i)));
      if (i + 1 < levels_.size()) {
        uint32_t below_per = units_per_instance(levels_[i + 1], units);
        inst.below = first[i + 1] + k * per / below_per;
      }
      instances_.push_back(std::move(inst));
    }
  }
  for (Instance& inst : instances_) {
    if (inst.below == kNoInstance) continue;
    inst.below_port = uint32_t(instances_[inst.below].ports.size());
    instances_[inst.below].ports.emplace_back();  // an instance above: no on_response
  }
}

void SharedLevelsModule::end_of_elaboration() {
  if (!memory_ && out.size() == 0)
    throw std::logic_error(std::string(name()) + ": no memory below (bind out or connect one)");
}

// After every socket has completed its binding at the end of elaboration.
void SharedLevelsModule::start_of_simulation() {
  for (size_t i = 0; i < instances_.size(); ++i)
    instances_[i].crossbar.add_units(uint32_t(instances_[i].ports.size()) +
                                     (i == 0 ? in.bound() : 0));
}

uint32_t SharedLevelsModule::entry(uint32_t unit) const {
  if (first_queued_ == levels_.size()) return 0;
  return unit / units_per_instance(levels_[first_queued_], units_);
}

uint32_t SharedLevelsModule::connect(uint32_t unit, std::function<void()> on_response) {
  Instance& inst = instances_[entry(unit)];
  inst.ports.push_back(on_response ? std::move(on_response) : std::function<void()>([] {}));
  return uint32_t(inst.ports.size() - 1);
}

std::pair<uint32_t, uint32_t> SharedLevelsModule::instances_of(uint32_t level) const {
  uint32_t begin = uint32_t(instances_.size()), end = 0;
  for (uint32_t i = 0; i < instances_.size(); ++i)
    if (instances_[i].level == level) {
      begin = std::min(begin, i);
      end = i + 1;
    }
  return {begin, std::max(begin, end)};
}

uint32_t SharedLevelsModule::slice_of(const Instance& inst, uint64_t addr) const {
  return slice_of_line(addr >> inst.line_shift, uint32_t(inst.slices.size()));
}

uint32_t SharedLevelsModule::warm(uint64_t addr, uint32_t bytes, bool write) {
  Instance& inst = instances_[0];
  if (inst.slices.empty()) return 0;
  Cycle now = clock_.cycles(sim_now());
  uint64_t line_bytes = levels_[inst.level].cache.line_bytes;
  uint32_t fetched = 0;
  for (uint64_t at = addr, end = addr + std::max<uint32_t>(bytes, 1); at < end;) {
    uint64_t stop = std::min(end, (at | (line_bytes - 1)) + 1);
    fetched += inst.slices[slice_of(inst, at)]->warm(at, uint32_t(stop - at), now, write);
    at = stop;
  }
  return fetched;
}

void SharedLevelsModule::track_cold_misses(uint64_t dense_begin, uint64_t dense_end) {
  for (Instance& inst : instances_)
    for (auto& slice : inst.slices) slice->track_cold_misses(dense_begin, dense_end);
}

bool SharedLevelsModule::tracks_cold_misses() const {
  return !instances_[0].slices.empty() && instances_[0].slices[0]->tracks_cold_misses();
}

void SharedLevelsModule::share_first_references(uint32_t level, double own_share,
                                                Cycle first_fetch_cycles) {
  auto [begin, end] = instances_of(level);
  for (uint32_t i = begin; i < end; ++i)
    for (auto& slice : instances_[i].slices)
      slice->share_first_references(own_share, first_fetch_cycles);
}

void SharedLevelsModule::use_timed_memory(uint32_t lead) {
  timed_below_ = true;
  window_ = std::min(lead + 1, lookahead_);
}

void SharedLevelsModule::connect_memory(QueuedMemory& memory, uint32_t lead) {
  memory_ = &memory;
  memory.answer_to(dram_answers_);
  use_timed_memory(lead);
}

void SharedLevelsModule::add_job(const Job& job, Cycle at) {
  events_.push(at, job);
  if (serving_ || at >= armed_) return;  // serve() arms wake_, or an earlier wake is pending
  armed_ = at;
  wake_.notify(clock_.delay_to(at));
}

void SharedLevelsModule::request(uint32_t instance, uint32_t port, JobKind kind, uint64_t addr,
                                 uint32_t bytes, Cycle at, ReadClient* client, uint64_t token) {
  Instance& inst = instances_[instance];
  Job job;
  job.kind = kind;
  job.instance = uint16_t(instance);
  job.port = port;
  job.slice = slice_of(inst, addr);
  job.addr = addr;
  job.bytes = bytes;
  job.client = client;
  job.token = token;
  Cycle sent = std::max(at, clock_.cycles(sim_now()));
  bool data = kind != JobKind::Read;  // a write or a fill carries its line
  Cycle arrives =
      inst.crossbar.to_slice(port, job.slice, sent, data ? bytes : Crossbar::kRequestBytes);
  // During serve() a unit may send a miss that waited for an MSHR freed by a response, and a
  // level's miss becomes a request at the next level: dated at or after the job being served,
  // it joins the calendar in order. From outside, a request dated inside the window already
  // served breaks the requesters' promise.
  if (!serving_ && arrives < served_until_)
    throw std::logic_error(std::string(name()) + ": a request dated cycle " +
                           std::to_string(arrives) + " came after cycle " +
                           std::to_string(served_until_) +
                           " was served: its requester breaks the lookahead of " +
                           std::to_string(lookahead_) + " cycles");
  if (!inst.slices.empty()) inst.slices[job.slice]->prime(addr);
  add_job(job, arrives);
}

tlm::tlm_sync_enum SharedLevelsModule::nb_transport_fw(int port, tlm::tlm_generic_payload& trans,
                                                       tlm::tlm_phase& phase,
                                                       sc_core::sc_time& delay) {
  if (phase != tlm::BEGIN_REQ) return tlm::TLM_COMPLETED;  // END_RESP: nothing left to do
  bool write = trans.get_command() == tlm::TLM_WRITE_COMMAND;
  if (!write && trans.get_command() != tlm::TLM_READ_COMMAND) {
    trans.set_response_status(tlm::TLM_COMMAND_ERROR_RESPONSE);
    return tlm::TLM_COMPLETED;
  }
  request(0, uint32_t(instances_[0].ports.size() + port), write ? JobKind::Write : JobKind::Read,
          trans.get_address(), trans.get_data_length(), clock_.cycles(sim_now() + delay), nullptr,
          reinterpret_cast<uint64_t>(&trans));
  if (write) {
    trans.set_response_status(tlm::TLM_OK_RESPONSE);
    return tlm::TLM_COMPLETED;
  }
  phase = tlm::END_REQ;
  return tlm::TLM_UPDATED;
}

void SharedLevelsModule::serve() {
  served_until_ = clock_.cycles(sim_now()) + window_;
  armed_ = kPending;
  serve_window();
}

void SharedLevelsModule::serve_window() {
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

void SharedLevelsModule::prime_next_job() const {
  Job next;
  if (!events_.peek(next)) return;
  bool answers = next.kind == JobKind::Read || next.kind == JobKind::DramDone;
  if (answers && next.client) next.client->prime_done(next.token);
  if (next.kind == JobKind::LevelDone) {
    const BelowRead& r = below_reads_[next.token];
    r.client->prime_done(r.token);
  }
}

void SharedLevelsModule::run_job(const Job& job, Cycle at) {
  Instance& inst = instances_[job.instance];
  switch (job.kind) {
    case JobKind::Read: {
      // The slice (or the memory below a memory port) reports a miss's data later (never during
      // the read) under the id of the record it then takes (nothing takes one during the read).
      uint32_t id = next_slot(missed_, free_missed_);
      ReadCharge charge;
      if (inst.slices.empty()) {
        missed_[take_slot(missed_, free_missed_)] = {job, charge};
        return below_read(job.instance, job.addr, job.bytes, at, this, id);
      }
      Cycle ready = inst.slices[job.slice]->read(job.addr, job.bytes, at, this, id, charge);
      if (ready != kPending) return respond(job, ready, charge);
      missed_[take_slot(missed_, free_missed_)] = {job, charge};
      return;
    }
    case JobKind::Write:
      if (inst.slices.empty()) return below_write(job.instance, job.kind, job.addr, job.bytes, at);
      return inst.slices[job.slice]->write(job.addr, job.bytes, at);
    case JobKind::Fill: return inst.slices[job.slice]->fill(job.addr, job.bytes, at);
    case JobKind::DramRead: {
      if (memory_) {
        uint32_t read = take_slot(below_reads_, free_below_reads_);
        below_reads_[read] = {job.client, job.token, {}};
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
    case JobKind::LevelDone: {
      BelowRead r = below_reads_[job.token];
      free_below_reads_.push_back(uint32_t(job.token));  // the answer may add jobs
      return r.client->read_done(r.token, at, r.charge);
    }
  }
}

void SharedLevelsModule::below_read(uint32_t instance, uint64_t addr, uint32_t bytes, Cycle at,
                                    ReadClient* client, uint64_t token) {
  const Instance& inst = instances_[instance];
  if (inst.below == kNoInstance) {
    Job job;
    job.kind = JobKind::DramRead;
    job.instance = uint16_t(instance);
    job.addr = addr;
    job.bytes = bytes;
    job.client = client;
    job.token = token;
    return add_job(job, at);
  }
  uint32_t read = take_slot(below_reads_, free_below_reads_);
  below_reads_[read] = {client, token, {}};
  request(inst.below, inst.below_port, JobKind::Read, addr, bytes, at, &level_answers_, read);
}

void SharedLevelsModule::below_write(uint32_t instance, JobKind kind, uint64_t addr, uint32_t bytes,
                                     Cycle at) {
  const Instance& inst = instances_[instance];
  if (inst.below != kNoInstance)
    return request(inst.below, inst.below_port, kind, addr, bytes, at, nullptr, 0);
  if (kind == JobKind::Fill)
    throw std::logic_error(std::string(name()) + ": a victim fill has no level to go to");
  Job job;
  job.kind = JobKind::DramWrite;
  job.instance = uint16_t(instance);
  job.addr = addr;
  job.bytes = bytes;
  add_job(job, at);
}

void SharedLevelsModule::read_done(uint64_t missed, Cycle ready, const ReadCharge& charge) {
  MissedRead m = missed_[missed];
  free_missed_.push_back(uint32_t(missed));  // the answer may add jobs
  m.charge += charge;
  respond(m.job, ready, m.charge);
}

inline void SharedLevelsModule::respond(const Job& job, Cycle ready, const ReadCharge& charge) {
  Instance& inst = instances_[job.instance];
  Cycle arrived = inst.crossbar.to_unit(job.slice, job.port, ready, job.bytes);
  if (job.port < inst.ports.size()) {
    job.client->read_done(job.token, arrived, charge);
    if (inst.ports[job.port]) inst.ports[job.port]();
    return;
  }
  auto& trans = *reinterpret_cast<tlm::tlm_generic_payload*>(job.token);
  trans.set_response_status(tlm::TLM_OK_RESPONSE);
  tlm::tlm_phase phase = tlm::BEGIN_RESP;
  sc_core::sc_time delay = clock_.time(arrived) - stamp_;  // serve() runs at stamp_
  in[int(job.port - inst.ports.size())]->nb_transport_bw(trans, phase, delay);
}

void SharedLevelsModule::prepare_below(tlm::tlm_generic_payload& t, tlm::tlm_command command,
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

std::runtime_error SharedLevelsModule::below_error(const tlm::tlm_generic_payload& t) {
  return std::runtime_error("memory access at " + std::to_string(t.get_address()) +
                            " failed: " + t.get_response_string());
}

Cycle SharedLevelsModule::send_below(tlm::tlm_command command, uint64_t addr, uint32_t bytes,
                                     Cycle at) {
  tlm::tlm_generic_payload& t = below_trans_;
  prepare_below(t, command, addr, bytes);
  sc_core::sc_time delay = clock_.time(at) - stamp_;
  out->b_transport(t, delay);
  if (t.is_response_error()) throw below_error(t);
  return clock_.cycles(stamp_ + delay);
}

void SharedLevelsModule::send_timed(const Job& job, Cycle at) {
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

tlm::tlm_sync_enum SharedLevelsModule::nb_transport_bw(tlm::tlm_generic_payload& trans,
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

void SharedLevelsModule::below_done(BelowTransaction& t, Cycle ready) {
  below_free_.push_back(&t);
  if (t.client) answer_below(JobKind::DramDone, t.client, t.token, ready);  // else a write's
}

// A DRAM read's answer frees its record at once (the DRAM charges nothing).
void SharedLevelsModule::DramAnswers::read_done(uint64_t read, Cycle ready, const ReadCharge&) {
  BelowRead r = m.below_reads_[read];
  m.free_below_reads_.push_back(uint32_t(read));
  m.answer_below(JobKind::DramDone, r.client, r.token, ready);
}

// A level's answer keeps its record, with what the read cost there, until it is served.
void SharedLevelsModule::LevelAnswers::read_done(uint64_t read, Cycle ready,
                                                 const ReadCharge& charge) {
  m.below_reads_[read].charge = charge;
  m.answer_below(JobKind::LevelDone, nullptr, read, ready);
}

void SharedLevelsModule::answer_below(JobKind kind, ReadClient* client, uint64_t token,
                                      Cycle ready) {
  Job job;
  job.kind = kind;
  job.client = client;
  job.token = token;
  // Outside serve(), a response dated inside the window already served (a memory that answers
  // with less lead than the window) is served now, in order with what it starts there.
  bool late = !serving_ && ready < served_until_;
  add_job(job, ready);
  if (late) serve_window();
}

}  // namespace rtsim
