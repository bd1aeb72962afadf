#include "model/sc/shared_levels_module.h"

#include <algorithm>
#include <sstream>
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
    module_.below_write(instance_, RequestKind::Write, addr, bytes, at);
  }
  void fill(uint64_t addr, uint32_t bytes, Cycle at) override {
    module_.below_write(instance_, RequestKind::Fill, addr, bytes, at);
  }

 private:
  SharedLevelsModule& module_;
  uint32_t instance_;
};

// `out` as the memory below the last level: loosely timed (b_transport: a read's data cycle at
// once) or, after use_timed_memory, approximately timed (a read's answer comes through
// nb_transport_bw, or at once when the target completes it in the call; either way it is queued
// as the read's Reply job, so the module's answer never runs inside the read call).
class SharedLevelsModule::OutPort : public MemoryTarget {
 public:
  explicit OutPort(SharedLevelsModule& module) : module_(module) {}
  Cycle read(uint64_t addr, uint32_t bytes, Cycle at, ReadClient*, uint64_t request,
             ReadCharge&) override {
    if (!timed) return module_.send_below(tlm::TLM_READ_COMMAND, addr, bytes, at);
    module_.send_timed(false, addr, bytes, at, request);
    return kPending;
  }
  void write(uint64_t addr, uint32_t bytes, Cycle at) override {
    if (timed) return module_.send_timed(true, addr, bytes, at, 0);
    module_.send_below(tlm::TLM_WRITE_COMMAND, addr, bytes, at);
  }
  bool timed = false;

 private:
  SharedLevelsModule& module_;
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
      out_port_(std::make_unique<OutPort>(*this)),
      memory_(out_port_.get()),
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

SharedLevelsModule::~SharedLevelsModule() = default;

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
  if (memory_ == out_port_.get() && out.size() == 0)
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
  out_port_->timed = true;
  window_ = std::min(lead + 1, lookahead_);
}

void SharedLevelsModule::connect_memory(MemoryTarget& memory, uint32_t lead) {
  memory_ = &memory;
  window_ = std::min(lead + 1, lookahead_);
}

void SharedLevelsModule::add_job(const Job& job, Cycle at) {
  events_.push(at, job);
  if (serving_ || at >= armed_) return;  // serve() arms wake_, or an earlier wake is pending
  armed_ = at;
  wake_.notify(clock_.delay_to(at));
}

uint32_t SharedLevelsModule::new_request(const MemRequest& r) {
  uint32_t id = take_slot(requests_, free_requests_);
  requests_[id] = r;
  return id;
}

void SharedLevelsModule::request(uint32_t instance, uint32_t port, RequestKind kind, uint64_t addr,
                                 uint32_t bytes, Cycle at, Answer answer, ReadClient* client,
                                 uint64_t token, tlm::tlm_generic_payload* transaction) {
  Instance& inst = instances_[instance];
  uint32_t id = take_slot(requests_, free_requests_);
  MemRequest& r = requests_[id];
  r.addr = addr;
  r.bytes = bytes;
  r.kind = kind;
  r.answer = answer;
  r.to_dram = false;
  r.instance = uint16_t(instance);
  r.port = port;
  r.slice = slice_of(inst, addr);
  r.client = client;
  r.token = token;
  r.transaction = transaction;
  r.charge = {};
  Cycle sent = std::max(at, clock_.cycles(sim_now()));
  // It crosses to its slice when the calendar reaches the earliest cycle it can arrive, so that
  // requesters running ahead book nothing shared (crossed at once where the crossbar is free).
  Cycle earliest = inst.crossbar.earliest(sent);
  // During serve() a unit may send a miss that waited for an MSHR freed by a response, and a
  // level's miss becomes a request at the next level: dated at or after the job being served,
  // it joins the calendar in order. From outside, a request dated inside the window already
  // served breaks the requesters' promise.
  if (!serving_ && earliest < served_until_) {
    free_request(id);
    throw std::logic_error(std::string(name()) + ": a request dated cycle " +
                           std::to_string(earliest) + " came after cycle " +
                           std::to_string(served_until_) +
                           " was served: its requester breaks the lookahead of " +
                           std::to_string(lookahead_) + " cycles");
  }
  r.wait = inst.crossbar.modelled() ? RequestWait::Crossbar : RequestWait::Slice;
  r.since = inst.crossbar.modelled() ? sent : earliest;
  if (!inst.slices.empty()) inst.slices[r.slice]->prime(addr);
  add_job({JobKind::Serve, id}, earliest);
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
  request(0, uint32_t(instances_[0].ports.size() + port),
          write ? RequestKind::Write : RequestKind::Read, trans.get_address(),
          trans.get_data_length(), clock_.cycles(sim_now() + delay), Answer::Initiator, nullptr, 0,
          &trans);
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
  const MemRequest& r = requests_[next.request];
  bool answers = next.kind == JobKind::Reply || (r.kind == RequestKind::Read && !r.to_dram);
  if (answers && r.client) r.client->prime_done(r.token);
}

void SharedLevelsModule::run_job(const Job& job, Cycle at) {
  uint32_t id = job.request;
  if (job.kind == JobKind::Reply) {
    const MemRequest& r = requests_[id];
    ReadClient* client = r.client;
    uint64_t token = r.token;
    ReadCharge charge = r.charge;
    free_request(id);  // the answer may add requests
    return client->read_done(token, at, charge);
  }
  if (requests_[id].to_dram) return access_dram(id, at);
  MemRequest& r = requests_[id];
  uint32_t instance = r.instance;
  Instance& inst = instances_[instance];
  if (r.wait == RequestWait::Crossbar) {  // sent at r.since; a write or a fill carries its line
    uint32_t bytes = r.kind == RequestKind::Read ? Crossbar::kRequestBytes : r.bytes;
    Cycle arrives = inst.crossbar.to_slice(r.port, r.slice, r.since, bytes);
    r.wait = RequestWait::Slice;
    r.since = arrives;
    if (arrives > at) return add_job(job, arrives);  // its links were busy
  }
  uint64_t addr = r.addr;
  uint32_t bytes = r.bytes, slice = r.slice;
  switch (r.kind) {
    case RequestKind::Read: {
      // A miss is reported later (never during the read) to read_done under the record's id.
      r.wait = RequestWait::Below;
      r.since = at;
      if (inst.slices.empty()) return below_read(instance, addr, bytes, at, this, id);
      ReadCharge charge;
      Cycle ready = inst.slices[slice]->read(addr, bytes, at, this, id, charge);
      if (ready != kPending) return respond(id, ready, charge);
      requests_[id].charge = charge;  // the read may have added records: r may have moved
      return;
    }
    case RequestKind::Write:
      free_request(id);
      if (inst.slices.empty()) return below_write(instance, RequestKind::Write, addr, bytes, at);
      return inst.slices[slice]->write(addr, bytes, at);
    case RequestKind::Fill: free_request(id); return inst.slices[slice]->fill(addr, bytes, at);
  }
}

void SharedLevelsModule::access_dram(uint32_t id, Cycle at) {
  MemRequest& r = requests_[id];
  if (r.kind == RequestKind::Write) {
    free_request(id);
    return memory_->write(r.addr, r.bytes, at);
  }
  r.wait = RequestWait::Dram;
  r.since = at;
  ReadClient* client = r.client;
  uint64_t token = r.token;
  ReadCharge none;
  Cycle ready = memory_->read(r.addr, r.bytes, at, &dram_answers_, id, none);
  if (ready == kPending) return;
  free_request(id);
  client->read_done(token, ready, {});
}

// A request of an instance with no level below it, for the DRAM.
MemRequest SharedLevelsModule::dram_request(uint32_t instance, uint64_t addr, uint32_t bytes,
                                            Cycle at) {
  MemRequest r;
  r.addr = addr;
  r.bytes = bytes;
  r.to_dram = true;
  r.instance = uint16_t(instance);
  r.wait = RequestWait::Dram;
  r.since = at;
  return r;
}

void SharedLevelsModule::below_read(uint32_t instance, uint64_t addr, uint32_t bytes, Cycle at,
                                    ReadClient* client, uint64_t token) {
  const Instance& inst = instances_[instance];
  if (inst.below != kNoInstance)
    return request(inst.below, inst.below_port, RequestKind::Read, addr, bytes, at, Answer::Level,
                   client, token);
  MemRequest r = dram_request(instance, addr, bytes, at);
  r.answer = Answer::Level;
  r.client = client;
  r.token = token;
  add_job({JobKind::Serve, new_request(r)}, at);
}

void SharedLevelsModule::below_write(uint32_t instance, RequestKind kind, uint64_t addr,
                                     uint32_t bytes, Cycle at) {
  const Instance& inst = instances_[instance];
  if (inst.below != kNoInstance)
    return request(inst.below, inst.below_port, kind, addr, bytes, at, Answer::Unit, nullptr, 0);
  if (kind == RequestKind::Fill)
    throw std::logic_error(std::string(name()) + ": a victim fill has no level to go to");
  MemRequest r = dram_request(instance, addr, bytes, at);
  r.kind = RequestKind::Write;
  add_job({JobKind::Serve, new_request(r)}, at);
}

void SharedLevelsModule::read_done(uint64_t request, Cycle ready, const ReadCharge& charge) {
  ReadCharge total = requests_[request].charge;
  total += charge;
  respond(uint32_t(request), ready, total);
}

ReadOrigin SharedLevelsModule::origin(uint64_t request) const {
  const MemRequest& r = requests_[request];
  return r.client ? r.client->origin(r.token) : ReadOrigin{};
}

inline void SharedLevelsModule::respond(uint32_t id, Cycle ready, const ReadCharge& charge) {
  MemRequest& r = requests_[id];
  Instance& inst = instances_[r.instance];
  Cycle arrived = inst.crossbar.to_unit(r.slice, r.port, ready, r.bytes);
  switch (r.answer) {
    case Answer::Unit: {
      ReadClient* client = r.client;
      uint64_t token = r.token;
      uint32_t port = r.port;
      free_request(id);  // the answer may add requests
      client->read_done(token, arrived, charge);
      inst.ports[port]();
      return;
    }
    case Answer::Level: r.charge = charge; return reply_at(id, arrived);
    case Answer::Initiator: {
      tlm::tlm_generic_payload& trans = *r.transaction;
      int socket = int(r.port - inst.ports.size());
      free_request(id);
      trans.set_response_status(tlm::TLM_OK_RESPONSE);
      tlm::tlm_phase phase = tlm::BEGIN_RESP;
      sc_core::sc_time delay = clock_.time(arrived) - stamp_;  // serve() runs at stamp_
      in[socket]->nb_transport_bw(trans, phase, delay);
      return;
    }
  }
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

void SharedLevelsModule::send_timed(bool write, uint64_t addr, uint32_t bytes, Cycle at,
                                    uint64_t request) {
  if (below_free_.empty()) {
    below_pool_.push_back(std::make_unique<BelowTransaction>());
    below_free_.push_back(below_pool_.back().get());
  }
  BelowTransaction& t = *below_free_.back();
  below_free_.pop_back();
  prepare_below(t, write ? tlm::TLM_WRITE_COMMAND : tlm::TLM_READ_COMMAND, addr, bytes);
  t.read = !write;
  t.request = uint32_t(request);
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
  if (t.read) reply_at(t.request, ready);  // else a write's
}

void SharedLevelsModule::reply_at(uint32_t request, Cycle ready) {
  requests_[request].wait = RequestWait::Data;
  requests_[request].since = ready;
  // Outside serve(), a response dated inside the window already served (a memory that answers
  // with less lead than the window) is served now, in order with what it starts there.
  bool late = !serving_ && ready < served_until_;
  add_job({JobKind::Reply, request}, ready);
  if (late) serve_window();
}

std::string SharedLevelsModule::waiting(size_t shown) const {
  std::vector<uint32_t> busy;
  for (uint32_t i = 0; i < requests_.size(); ++i)
    if (requests_[i].wait != RequestWait::Free) busy.push_back(i);
  std::stable_sort(busy.begin(), busy.end(),
                   [&](uint32_t a, uint32_t b) { return requests_[a].since < requests_[b].since; });
  std::ostringstream out;
  static const char* const kKinds[] = {"read", "write", "fill"};
  for (size_t k = 0; k < std::min(shown, busy.size()); ++k) {
    const MemRequest& r = requests_[busy[k]];
    const Instance& inst = instances_[r.instance];
    out << "  ";
    if (r.to_dram)
      out << "dram below " << inst.name;
    else
      out << inst.name << (inst.slices.empty() ? "" : " slice " + std::to_string(r.slice));
    out << ": " << kKinds[int(r.kind)] << " of " << r.bytes << " bytes at 0x" << std::hex << r.addr
        << std::dec;
    if (r.answer == Answer::Initiator) {
      out << " for TLM initiator " << r.port - inst.ports.size();
    } else if (r.client) {
      out << origin_text(r.client->origin(r.token));
    }
    out << " waits for " << wait_name(r.wait) << " since cycle " << r.since << "\n";
  }
  if (busy.size() > shown) out << "  (" << busy.size() - shown << " more requests)\n";
  return out.str();
}

}  // namespace rtsim
