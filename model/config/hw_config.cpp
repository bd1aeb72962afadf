#include "model/config/hw_config.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "model/config/config_presets.h"
#include "model/config/config_reader.h"
#include "model/config/memory_config.h"
#include "model/energy/dram_energy.h"
#include "model/energy/process_node.h"
#include "model/config/dram_presets.h"
#include "traces/error.h"
#include "traces/memory_plan.h"
#include "traces/toml_text.h"

namespace rtsim {
namespace {

constexpr uint64_t kMaxU32 = 0xffffffffull;
using Zero = ConfigReader::Zero;

void read_shader(ConfigReader r, ShaderConfig& c) {
  std::string model = r.text("model", shader_model_name(c.model),
                             "the SM around each RT unit: none (the unit takes rays straight from "
                             "the dispatcher) or simt (ray generation, hit and miss shading, warp "
                             "slots and shading reads; model/SIM.md, \"The shader side\"); "
                             "any-hit calls (shader.anyhit_*) are timed either way",
                             {"none", "simt"});
  c.model = model == "simt" ? ShaderModel::Simt : ShaderModel::None;
  c.warps = uint32_t(r.integer("warps", c.warps, "warps",
                               "simt: warp slots of the SM: warps generating, tracing or shading",
                               1, 4096));
  c.schedulers = uint32_t(r.integer("schedulers", c.schedulers, "schedulers",
                                    "simt: warp schedulers of the SM, one warp instruction a "
                                    "cycle each",
                                    1, 64));
  c.trace_latency = uint32_t(r.integer("trace_latency", c.trace_latency, "cycles",
                                       "simt: a trace call's hand-off each way between the SM "
                                       "and its RT unit",
                                       0, 100000));
  c.bytes_per_hit = uint32_t(r.integer("bytes_per_hit", c.bytes_per_hit, "bytes",
                                       "simt: what hit shading reads per hit (G-buffer, "
                                       "textures, payload) through the unit's L1",
                                       0, 65536));
  for (int t = 0; t < kRayTypeCount; ++t) {
    const char* type = ray_type_name(RayType(t));
    ConfigReader section = r.section(type);
    ShaderCycles& cycles = c.cycles[t];
    auto read = [&](const char* key, uint32_t& value, const char* what) {
      value = uint32_t(section.integer(
          key, value, "cycles", fmt::format("simt: {} of a warp of {} rays", what, type).c_str(), 0,
          1000000));
    };
    read("raygen", cycles.raygen, "ray generation");
    read("hit", cycles.hit, "hit shading");
    read("miss", cycles.miss, "miss shading");
  }
}

void read_banked_dram(ConfigReader dram, BankedDramConfig& c) {
  auto count = [&](const char* key, uint32_t& value, const char* unit, const char* desc,
                   uint64_t lo,
                   uint64_t hi) { value = uint32_t(dram.integer(key, value, unit, desc, lo, hi)); };
  c.clock_mhz = dram.real("clock_mhz", c.clock_mhz, "MHz", "banked: command clock CK", 1, 1e5);
  count("channels", c.channels, "channels", "banked: independent channels, each with its queues", 1,
        1024);
  count("ranks", c.ranks, "ranks", "banked: ranks per channel", 1, 16);
  count("bank_groups", c.bank_groups, "groups", "banked: bank groups per rank", 1, 64);
  count("banks_per_group", c.banks_per_group, "banks", "banked: banks per bank group", 1, 64);
  count("rows", c.rows, "rows", "banked: rows per bank", 1, 1u << 24);
  auto size = [&](const char* key, uint32_t& value, const char* desc, uint64_t lo, uint64_t hi) {
    value = uint32_t(dram.size(key, value, desc, lo, hi));
  };
  size("row_bytes", c.row_bytes, "banked: a row (page) of one channel", 8, 1 << 20);
  count("bus_bits", c.bus_bits, "bits", "banked: data bus width of a channel", 8, 1024);
  count("burst_length", c.burst_length, "beats", "banked: transfers of one RD or WR", 1, 64);
  count("beats_per_clock", c.beats_per_clock, "beats",
        "banked: data transfers per CK (data rate / CK)", 1, 16);
  c.mapping = dram.text("mapping", c.mapping,
                        "banked: address mapping: row_bank_column_channel, interleave, xor, or "
                        "a field order such as row:rank:bank:bankgroup:column:channel");
  size("interleave_bytes", c.interleave_bytes,
       "banked: bytes of a row one channel takes before the next (interleave, xor)", 1, 1 << 20);
  std::string page =
      dram.text("page_policy", c.page_policy == DramPagePolicy::Closed ? "closed" : "open",
                "banked: open keeps a row open until a conflict; closed "
                "precharges after the access unless a queued request hits the row",
                {"open", "closed"});
  c.page_policy = page == "closed" ? DramPagePolicy::Closed : DramPagePolicy::Open;
  std::string refresh = dram.text(
      "refresh",
      c.refresh == DramRefresh::PerBank ? "per_bank"
      : c.refresh == DramRefresh::None  ? "none"
                                        : "all_bank",
      "banked: all_bank (REFab every tREFI), per_bank (REFpb every tREFIpb, bank after bank) "
      "or none",
      {"all_bank", "per_bank", "none"});
  c.refresh = refresh == "per_bank" ? DramRefresh::PerBank
              : refresh == "none"   ? DramRefresh::None
                                    : DramRefresh::AllBank;
  count("read_queue", c.read_queue, "entries",
        "banked: read queue per channel (an entry: a request's bursts in one row)", 1, 4096);
  count("write_queue", c.write_queue, "entries", "banked: write queue per channel", 1, 4096);
  count("write_high", c.write_high, "entries", "banked: queued writes that start a write drain", 1,
        4096);
  count("write_low", c.write_low, "entries", "banked: a write drain stops at this many", 0, 4096);
  count("starvation_cap", c.starvation_cap, "requests",
        "banked: younger row hits served before the oldest request (FR-FCFS cap)", 0, 1 << 20);
  count("controller_latency", c.controller_latency, "cycles",
        "banked: controller and PHY, added to every read (core cycles)", 0, 100000);
  ConfigReader t = dram.section("timing");
  auto clocks = [&](const char* key, uint32_t& value, const char* desc) {
    value = uint32_t(t.integer(key, value, "tCK", desc, 0, 1u << 24));
  };
  DramTiming& d = c.timing;
  clocks("tCL", d.tCL, "banked: RD to its first data");
  clocks("tCWL", d.tCWL, "banked: WR to its first data");
  clocks("tRCD_RD", d.tRCD_RD, "banked: ACT to RD, same bank");
  clocks("tRCD_WR", d.tRCD_WR, "banked: ACT to WR, same bank");
  clocks("tRP", d.tRP, "banked: PRE to ACT, same bank");
  clocks("tRAS", d.tRAS, "banked: ACT to PRE, same bank");
  clocks("tRC", d.tRC, "banked: ACT to ACT, same bank");
  clocks("tCCD_S", d.tCCD_S, "banked: column to column command, other bank group");
  clocks("tCCD_L", d.tCCD_L, "banked: column to column command, same bank group");
  clocks("tRRD_S", d.tRRD_S, "banked: ACT to ACT, other bank group");
  clocks("tRRD_L", d.tRRD_L, "banked: ACT to ACT, same bank group");
  clocks("tFAW", d.tFAW, "banked: window of at most four ACTs per rank");
  clocks("tWTR_S", d.tWTR_S, "banked: end of write data to RD, other bank group");
  clocks("tWTR_L", d.tWTR_L, "banked: end of write data to RD, same bank group");
  clocks("tWR", d.tWR, "banked: end of write data to PRE, same bank");
  clocks("tRTP", d.tRTP, "banked: RD to PRE, same bank");
  clocks("tRTW", d.tRTW, "banked: RD to WR, same rank (read-to-write turnaround)");
  clocks("tRTRS", d.tRTRS, "banked: data bus gap when it passes to another rank");
  clocks("tREFI", d.tREFI, "banked: all-bank refresh interval");
  clocks("tRFC", d.tRFC, "banked: all-bank refresh: the rank is blocked this long");
  clocks("tREFIpb", d.tREFIpb, "banked: per-bank refresh interval (one bank after the other)");
  clocks("tRFCpb", d.tRFCpb, "banked: per-bank refresh: the bank is blocked this long");
  ConfigReader energy = dram.section("energy");
  c.energy_device = energy.text("device", c.energy_device,
                                "the device whose data-sheet currents give the command energies "
                                "(model/energy/SOURCES.md, D.2), scaled to this one's bursts, "
                                "rows and capacity",
                                dram_energy_device_names());
  c.io_pj_per_bit =
      energy.real("io_pj_per_bit", c.io_pj_per_bit, "pJ/bit",
                  "I/O energy of a bit crossing the bus (the currents leave it out)", 0, 1000);
}

void read_test_units(ConfigReader r, TestUnitConfig& c, const char* tests) {
  c.count = uint32_t(r.integer("count", c.count, "units", "identical pipelined units", 1, 64));
  c.issue_width = uint32_t(r.integer("issue_width", c.issue_width, "tests",
                                     fmt::format("{} one issue tests", tests).c_str(), 1, 64));
  c.latency =
      uint32_t(r.integer("latency", c.latency, "cycles", "from an issue to its results", 1, 10000));
}

void read_ray_buffer(ConfigReader& tq, RayBufferConfig& b) {
  std::string place = tq.text("buffer", ray_buffer_place_name(b.place),
                              "where queued rays' states wait: a dedicated SRAM, or memory "
                              "through the L1, L2 and DRAM",
                              {"sram", "memory"});
  b.place = place == "memory" ? RayBufferPlace::Memory : RayBufferPlace::Sram;
  b.bytes = tq.size("buffer_bytes", b.bytes,
                    "SRAM ray buffer; 0: room for max_rays states (model/sched/ray_buffer.h)", 0,
                    uint64_t(1) << 40);
  std::string overflow =
      tq.text("overflow", ray_buffer_overflow_name(b.overflow),
              "full SRAM: hold fresh rays back and let postponed rays go on (hold), or put "
              "further states in memory (spill)",
              {"hold", "spill"});
  b.overflow = overflow == "spill" ? RayBufferOverflow::Spill : RayBufferOverflow::Hold;
  b.banks = uint32_t(
      tq.integer("buffer_banks", b.banks, "banks", "SRAM banks, each with its own port", 1, 1024));
  b.bytes_per_cycle = uint32_t(
      tq.integer("buffer_bytes_per_cycle", b.bytes_per_cycle, "bytes/cycle",
                 "each SRAM bank's port, reads and writes, in whole bytes; 0 = no limit, else 1 to "
                 "4294967295",
                 0, kMaxU32));
  b.latency = uint32_t(tq.integer("buffer_latency", b.latency, "cycles",
                                  "SRAM access after the transfer", 0, 100000));
}

// Every key of the config, read once, here. Defaults are the values already in `c`.
void read_hw_config(ConfigReader& r, HwConfig& c) {
  c.name = r.text("name", c.name, "the preset's name, carried into results");
  c.description = r.text("description", c.description, "what the preset models");
  c.clock_ghz =
      r.section("clock").real("ghz", c.clock_ghz, "GHz",
                              "clock of every unit; MRays/s = rays per cycle * clock", 0.001, 100);

  ConfigReader sim = r.section("sim");
  c.sim.quantum_cycles = uint32_t(sim.integer(
      "quantum_cycles", c.sim.quantum_cycles, "cycles",
      "how far a unit may run ahead of SystemC time (TLM temporal decoupling; 1 = exact order)", 1,
      1 << 20));
  c.sim.stall_cycles = sim.integer(
      "stall_cycles", c.sim.stall_cycles, "cycles",
      "no progress for this long, with nothing scheduled, stops the run with a stall error", 1,
      1ull << 40);
  c.sim.warmup_rays = sim.integer(
      "warmup_rays", c.sim.warmup_rays, "rays",
      "the stream's first rays run with full timing but are left out of every stat", 0, 1ull << 40);
  c.sim.warmup_frames = uint32_t(sim.integer(
      "warmup_frames", c.sim.warmup_frames, "frames",
      "the stream's first frames, likewise (with warmup_rays: whichever ends later)", 0, 100000));

  ConfigReader dispatch = r.section("dispatch");
  c.dispatch.rays_per_cycle =
      dispatch.rate("rays_per_cycle", c.dispatch.rays_per_cycle, "rays/cycle",
                    "ray delivery bandwidth to all units", 0.001, 1e6, Zero::Refused);
  c.dispatch.latency = uint32_t(dispatch.integer(
      "latency", c.dispatch.latency, "cycles", "from delivery to arrival at the unit", 0, 100000));

  ConfigReader sort = r.section("sort");
  SortConfig& so = c.sort;
  std::string key = sort.text("key", sort_key_name(so.key),
                              "ray sorting unit between dispatch and the units: off, origin cell "
                              "and direction octant, or a hash of origin cell and direction",
                              {"none", "octant_cell", "hash"});
  so.key = key == "octant_cell" ? SortKey::OctantCell
           : key == "hash"      ? SortKey::Hash
                                : SortKey::None;
  so.buffer_rays = uint32_t(sort.integer("buffer_rays", so.buffer_rays, "rays",
                                         "rays the sorting buffer holds", 1, 1 << 24));
  so.latency = uint32_t(sort.integer(
      "latency", so.latency, "cycles",
      "from the forming of a group (once enough rays arrived) to the unit", 0, 100000));
  so.grid = uint32_t(sort.integer("grid", so.grid, "cells",
                                  "origin cells per axis over the scene's bounds", 1, 1024));
  so.direction_bins =
      uint32_t(sort.integer("direction_bins", so.direction_bins, "steps",
                            "hash: quantisation steps per direction component", 1, 1024));
  so.bins = uint32_t(
      sort.integer("bins", so.bins, "bins", "hash: bins the key is hashed into", 1, 1 << 24));
  so.max_age = uint32_t(sort.integer("max_age", so.max_age, "buffers",
                                     "a ray overtaken by max_age * buffer_rays later rays has its "
                                     "bin served first; 0: never",
                                     0, 1 << 20));

  ConfigReader rt = r.section("rt");
  c.rt_units =
      uint32_t(rt.integer("count", c.rt_units, "units", "RT units, each with its L1", 1, 1024));
  std::string mode = rt.text("mode", traversal_mode_name(c.rt.mode),
                             "traversal: per-ray depth-first, treelet queues, warp packets",
                             {"depth_first", "treelet", "packet"});
  c.rt.mode = mode == "treelet"  ? TraversalMode::Treelet
              : mode == "packet" ? TraversalMode::Packet
                                 : TraversalMode::DepthFirst;
  std::string refill =
      rt.text("refill", refill_name(c.rt.refill),
              "depth_first: new rays once a warp's rays all retired (warp) or into each slot as "
              "its ray retires (slot); treelet mode refills slots, packet mode warps",
              {"warp", "slot"});
  c.rt.refill = refill == "slot" ? Refill::Slot : Refill::Warp;
  c.rt.warps = uint32_t(rt.integer("warps", c.rt.warps, "warps", "warp slots per unit", 1, 1024));
  c.rt.warp_size = uint32_t(rt.integer("warp_size", c.rt.warp_size, "rays",
                                       "rays per warp; ray slots = warps * warp_size", 1, 256));
  c.rt.issue_per_cycle = uint32_t(
      rt.integer("issue_per_cycle", c.rt.issue_per_cycle, "steps",
                 "steps traversal control starts per cycle (packet mode: warp steps)", 1, 1024));
  c.rt.setup_latency = uint32_t(rt.integer("setup_latency", c.rt.setup_latency, "cycles",
                                           "ray setup, from arrival to the first step", 0, 100000));
  c.rt.control_latency =
      uint32_t(rt.integer("control_latency", c.rt.control_latency, "cycles",
                          "stack pop, sort and push after a step's tests", 0, 100000));
  std::string issue = rt.text("test_issue", test_issue_name(c.rt.test_issue),
                              "separate: box and triangle units issue apart; shared: each of "
                              "box.count units starts a box or a triangle issue a cycle (AMD)",
                              {"separate", "shared"});
  c.rt.test_issue = issue == "shared" ? TestIssue::Shared : TestIssue::Separate;
  ConfigReader stack = rt.section("stack");
  c.rt.stack.entries =
      uint32_t(stack.integer("entries", c.rt.stack.entries, "entries",
                             "on-chip stack depth per ray; deeper entries spill", 1, 4096));
  c.rt.stack.entry_bytes =
      uint32_t(stack.size("entry_bytes", c.rt.stack.entry_bytes, "one spilled stack entry", 1, 64));
  read_test_units(rt.section("box"), c.rt.box, "child boxes");
  read_test_units(rt.section("triangle"), c.rt.triangle, "triangles");
  read_test_units(rt.section("transform"), c.rt.transform,
                  "rays (instance transforms: two levels)");
  ConfigReader packet = rt.section("packet");
  std::string policy =
      packet.text("policy", packet_policy_name(c.rt.packet_policy),
                  "packet mode: lanes that step together (node_first: while-while; majority)",
                  {"node_first", "majority"});
  c.rt.packet_policy = policy == "majority" ? PacketPolicy::Majority : PacketPolicy::NodeFirst;
  PacketReorderConfig& reorder = c.rt.reorder;
  reorder.below = packet.real("reorder_below", reorder.below, "fraction",
                              "packet mode: a packet whose step would use fewer of its lanes is "
                              "regrouped into two of half the width; 0 = never",
                              0, 1);
  reorder.min_width =
      uint32_t(packet.integer("min_width", reorder.min_width, "lanes",
                              "the narrowest packet reordering makes; warp_size / min_width must "
                              "be a power of two",
                              1, 256));
  reorder.latency = uint32_t(packet.integer("reorder_latency", reorder.latency, "cycles",
                                            "regrouping a packet's rays", 0, 100000));
  ConfigReader prefetch = rt.section("prefetch");
  PrefetchConfig& pf = c.rt.prefetch;
  std::string trigger = prefetch.text(
      "trigger", prefetch_trigger_name(pf.trigger),
      "treelet prefetching into the unit's L1: off, on a node step into a treelet not "
      "prefetched lately (first_visit), or on taking a batch from a treelet's queue (batch)",
      {"none", "first_visit", "batch"});
  pf.trigger = trigger == "first_visit" ? PrefetchTrigger::FirstVisit
               : trigger == "batch"     ? PrefetchTrigger::Batch
                                        : PrefetchTrigger::None;
  pf.batch_rays =
      uint32_t(prefetch.integer("batch_rays", pf.batch_rays, "rays",
                                "batch: the smallest batch that prefetches", 1, 1 << 24));
  pf.recent = uint32_t(prefetch.integer("recent", pf.recent, "treelets",
                                        "first_visit: the unit's last prefetched treelets, "
                                        "which it does not prefetch again",
                                        1, 4096));
  pf.max_bytes = uint32_t(prefetch.size("max_bytes", pf.max_bytes,
                                        "most bytes one prefetch fetches, nodes first; 0 = "
                                        "the whole treelet",
                                        0, kMaxU32));

  ConfigReader shader = r.section("shader");
  AnyHitConfig& anyhit = c.rt.anyhit;
  anyhit.shader.latency = uint32_t(shader.integer(
      "anyhit_latency", anyhit.shader.latency, "cycles",
      "an any-hit call's round trip from the RT unit to the shader core and back (alpha-tested "
      "triangles; the texel read is timed through the L1)",
      1, 100000));
  anyhit.shader.count = uint32_t(
      shader.integer("anyhit_per_cycle", anyhit.shader.count, "calls",
                     "any-hit calls the shader core starts per cycle for one RT unit", 1, 64));
  anyhit.read_bytes = uint32_t(shader.size("anyhit_read_bytes", anyhit.read_bytes,
                                           "texture bytes one any-hit call reads", 1, 4096));
  read_shader(shader, c.shader);

  ConfigReader tq = r.section("treelet_queues");
  c.treelet_queues.policy = tq.text("policy", c.treelet_queues.policy,
                                    "which queue a unit serves next", treelet_policy_names());
  c.treelet_queues.max_rays = uint32_t(
      tq.integer("max_rays", c.treelet_queues.max_rays, "rays",
                 "ray buffer: rays queued plus executing (memory grows with it)", 1, 1 << 24));
  c.treelet_queues.queue_capacity = uint32_t(tq.integer(
      "queue_capacity", c.treelet_queues.queue_capacity, "rays",
      "most rays one treelet's queue holds; a full queue lets the ray go on", 1, kMaxU32));
  c.treelet_queues.min_batch = uint32_t(
      tq.integer("min_batch", c.treelet_queues.min_batch, "rays",
                 "a queue this long is served before fresh rays are admitted", 1, kMaxU32));
  c.treelet_queues.enqueue_latency =
      uint32_t(tq.integer("enqueue_latency", c.treelet_queues.enqueue_latency, "cycles",
                          "from postponing a ray to it being queued", 0, 100000));
  c.treelet_queues.dequeue_latency =
      uint32_t(tq.integer("dequeue_latency", c.treelet_queues.dequeue_latency, "cycles",
                          "from a unit taking a ray to its next step", 0, 100000));
  read_ray_buffer(tq, c.treelet_queues.buffer);

  read_memory_levels(r.section("memory"), c.memory);

  ConfigReader dram = r.section("dram");
  std::string model = dram.text("model", c.dram_model == DramModel::Banked ? "banked" : "simple",
                                "simple: one bus with a fixed latency; banked: channels, banks, "
                                "row buffers, refresh and a scheduling controller",
                                {"simple", "banked"});
  c.dram_model = model == "banked" ? DramModel::Banked : DramModel::Simple;
  c.dram.bytes_per_cycle =
      dram.rate("bytes_per_cycle", c.dram.bytes_per_cycle, "bytes/cycle",
                "simple: peak bandwidth of the data bus", 0.001, kMaxBytesPerCycle, Zero::Refused);
  c.dram.latency =
      uint32_t(dram.integer("latency", c.dram.latency, "cycles",
                            "simple: from the end of a transfer to data ready", 0, 1000000));
  c.dram.queue_depth =
      uint32_t(dram.integer("queue_depth", c.dram.queue_depth, "requests",
                            "simple: requests that may wait for the bus", 1, 1 << 20));
  c.dram.burst_bytes = uint32_t(dram.size("burst_bytes", c.dram.burst_bytes,
                                          "simple: smallest transfer, a power of two", 1, 4096));
  std::string preset =
      dram.text("preset", c.banked_dram.preset,
                "banked: the device and timing preset (configs/dram/); the keys below override it",
                dram_preset_names());
  if (preset != c.banked_dram.preset) c.banked_dram = dram_preset_config(preset);
  read_banked_dram(dram, c.banked_dram);

  ConfigReader bvh = r.section("bvh");
  c.bvh.width =
      int(bvh.integer("width", uint64_t(c.bvh.width), "children", "most children of a node", 2, 8));
  std::string format = bvh.text("node_format", node_format_name(c.bvh.node_format),
                                "node encoding: fp32 boxes, compressed 8-wide (Ylitie 2017), "
                                "AMD RDNA2/3's 4-wide fp32 or fp16 nodes (Mesa radv), or Intel "
                                "Xe's 6-wide (Mesa anv; with triangle_format xe_quad)",
                                node_format_names());
  c.bvh.node_format = *node_format_from_name(format);
  std::string triangles = bvh.text("triangle_format", triangle_format_name(c.bvh.triangle_format),
                                   "triangle encoding: raw vertices, Woop transform, AMD's "
                                   "triangle node, or Intel Xe's quad (with xe6)",
                                   triangle_format_names());
  c.bvh.triangle_format = *triangle_format_from_name(triangles);
  std::string layout =
      bvh.text("layout", node_layout_name(c.bvh.node_layout), "node order in memory",
               {"depth-first", "breadth-first", "treelet"});
  c.bvh.node_layout = *node_layout_from_name(layout);
  c.bvh.treelet_bytes =
      uint32_t(bvh.size("treelet_bytes", c.bvh.treelet_bytes, "budget of one treelet", 512, 65536));
  std::string budget = bvh.text("treelet_budget", treelet_budget_name(c.bvh.treelet_budget),
                                "what the treelet budget counts: its nodes, or its nodes and the "
                                "triangles of their leaves",
                                {"nodes", "nodes_and_triangles"});
  c.bvh.treelet_budget = *treelet_budget_from_name(budget);
  c.bvh.node_align = uint32_t(bvh.integer(
      "node_align", c.bvh.node_align, "bytes",
      "0 packs nodes; a power of two (the L1 line or sector) pads them so that none spans more "
      "blocks of it than it fills",
      0, 4096));
  c.bvh.max_leaf_size = int(bvh.integer("max_leaf_size", uint64_t(c.bvh.max_leaf_size), "triangles",
                                        "most triangles in one leaf", 1, 16));
  c.bvh.sah_bins = int(bvh.integer("sah_bins", uint64_t(c.bvh.sah_bins), "bins",
                                   "bins per axis of the binned SAH build: 16 or 32", 16, 32));
  std::string instancing =
      bvh.text("instancing", instancing_name(c.bvh.instancing),
               "levels: two (a TLAS over instances, a BLAS per mesh) when the scene places a mesh "
               "more than once (auto), always (two_level; a flat scene is one instance), or one "
               "over the world-space triangles (flatten)",
               {"auto", "flatten", "two_level"});
  c.bvh.instancing = *instancing_from_name(instancing);

  ConfigReader energy = r.section("energy");
  std::vector<std::string> nodes;
  for (const ProcessNode& node : process_nodes()) nodes.push_back(node.name);
  c.energy.node =
      energy.text("node", c.energy.node,
                  "process node of the energy and area model (model/energy/README.md)", nodes);
  c.energy.sram_leak_mw_per_kb =
      energy.real("sram_leak_mw_per_kb", c.energy.sram_leak_mw_per_kb, "mW/KB",
                  "static power of SRAM (caches, ray buffer), per KB", 0, 100);
  c.energy.logic_leak_share = energy.real(
      "logic_leak_share", c.energy.logic_leak_share, "fraction",
      "static power of the test units and ray registers as a share of their peak dynamic power", 0,
      10);
  c.energy.wire_mm = energy.real("wire_mm", c.energy.wire_mm, "mm",
                                 "distance a byte travels between an L1 and the L2", 0, 1000);
}

std::string toml_literal(const nlohmann::ordered_json& value) {
  if (value.is_string()) return value.dump();  // JSON string escapes are valid TOML
  if (value.is_number_float()) {
    std::string text = fmt::format("{}", value.get<double>());
    if (text.find_first_of(".e") == std::string::npos) text += ".0";
    return text;
  }
  return value.dump();
}

ConfigReadContext resolve(const HwConfig& config) {
  ConfigReadContext ctx;
  ConfigReader reader(nullptr, "", ctx);
  HwConfig copy = config;
  read_hw_config(reader, copy);
  return ctx;
}

// The file's keys with the overrides applied, each checked on its own (type, range, unknown).
HwConfig read_keys(const std::string& path, const std::vector<std::string>& overrides,
                   ConfigReadContext& ctx) {
  std::string file = hw_config_path(path);
  toml::table root = parse_config_file(file, "hardware config");
  ctx.file = file.empty() ? "(defaults)" : file;
  name_memory_levels(root, ctx);
  for (const std::string& assignment : overrides) apply_override(root, assignment, ctx);
  expand_cache_shorthand(root, ctx);
  HwConfig config;
  ConfigReader reader(&root, "", ctx);
  read_hw_config(reader, config);
  check_unknown_keys(root, ctx);
  return config;
}

}  // namespace

BankedDramConfig dram_preset_config(const std::string& name) {
  const auto& presets = dram_presets();
  auto it = std::find_if(presets.begin(), presets.end(),
                         [&](const DramPreset& p) { return name == p.name; });
  std::string file = "configs/dram/" + name + ".toml";
  if (it == presets.end())
    throw_input_error("dram.preset", "",
                      fmt::format("'{}' is not a DRAM preset (known: {})", name,
                                  fmt::join(dram_preset_names(), ", ")));
  toml::table root = parse_toml(it->toml, file);
  ConfigReadContext ctx;
  ctx.file = file;
  ConfigReader reader(&root, "", ctx);
  BankedDramConfig c;
  read_banked_dram(reader.section("dram"), c);
  check_unknown_keys(root, ctx);
  c.preset = name;
  std::string problem = banked_dram_config_problem(c);
  if (!problem.empty()) throw_input_error(file, "", "[dram] " + problem);
  return c;
}

const BankedDramConfig& default_banked_dram() {
  static const BankedDramConfig config = dram_preset_config("gddr6-16");
  return config;
}

DramConfig dram_for_analysis(const HwConfig& config) {
  if (config.dram_model == DramModel::Simple) return config.dram;
  const BankedDramConfig& b = config.banked_dram;
  DramConfig d = config.dram;
  d.bytes_per_cycle = b.peak_gb_per_s() / config.clock_ghz;
  double closed_ns = double(b.timing.tRCD_RD + b.timing.tCL) * 1000.0 / b.clock_mhz;
  d.latency = uint32_t(std::ceil(closed_ns * config.clock_ghz)) + b.controller_latency;
  d.queue_depth = b.channels * b.read_queue;
  d.burst_bytes = b.burst_bytes();
  return d;
}

std::vector<MemoryLevelConfig> default_memory_levels() {
  MemoryLevelConfig l1, l2;
  l1.name = "l1";
  l1.cache = CacheConfig{32 * 1024, 64, 4, "lru", 20, 16};
  l2.name = "l2";
  l2.scope = LevelScope::Shared;
  l2.cache = CacheConfig{2 * 1024 * 1024, 64, 16, "lru", 80, 128};
  return {l1, l2};
}

std::vector<MemoryLevelConfig> levels_as_built(const HwConfig& config) {
  std::vector<MemoryLevelConfig> levels = config.memory;
  for (MemoryLevelConfig& level : levels)
    if (level.scope != LevelScope::Shared && config.rt.mode == TraversalMode::Treelet)
      level.cache.write_back = false;
  return levels;
}

const MemoryLevelConfig* find_level(const HwConfig& config, const std::string& name) {
  for (const MemoryLevelConfig& level : config.memory)
    if (level.name == name) return &level;
  return nullptr;
}

std::string two_level_problem(const HwConfig& c, const std::string& what) {
  if (c.memory.size() == 2 && c.memory[0].scope == LevelScope::Unit &&
      c.memory[1].scope == LevelScope::Shared && c.memory[1].fill == LevelFill::Miss)
    return {};
  std::string levels;
  for (const MemoryLevelConfig& l : c.memory)
    levels += (levels.empty() ? "" : ", ") + l.name + " (" + scope_name(l) + ")";
  return fmt::format(
      "{} models a unit level and one shared level; this machine has {} ({}): use `rtsim sim`",
      what, c.memory.size(), levels);
}

uint64_t ray_buffer_sram_bytes(const HwConfig& c) {
  const RayBufferConfig& b = c.treelet_queues.buffer;
  if (c.rt.mode != TraversalMode::Treelet || b.place == RayBufferPlace::Memory) return 0;
  // The SRAM as built: its configured bytes, even those too few for one more state.
  return b.bytes ? b.bytes : uint64_t(c.treelet_queues.max_rays) * ray_state_bytes(c.rt.stack);
}

uint32_t ray_slots(const HwConfig& c) {
  if (c.rt.mode == TraversalMode::Treelet) return c.treelet_queues.max_rays;
  uint32_t sorting = c.sort.key == SortKey::None ? 0 : c.sort.buffer_rays;
  return c.rt_units * c.rt.warps * c.rt.warp_size + sorting;
}

namespace {

// Measured peaks (bench-sim's child peak memory as each key grows), rounded up by a fifth or
// more: an RT unit's modules 84 KiB besides its slots and L1, a ray context 830 B, a sorting bin
// 24 B, a shader warp slot 56 B; a cache, its arrays (Cache::host_bytes) and a fourth more.
constexpr uint64_t kRtUnitBytes = 128 * 1024;
constexpr uint64_t kRayContextBytes = 1024;
constexpr uint64_t kSortBinBytes = 32;
constexpr uint64_t kShaderWarpBytes = 64;

uint64_t cache_host_bytes(const CacheConfig& c) {
  return Cache::host_bytes(c) / 4 * 5;
}

}  // namespace

SimHostMemory sim_host_memory(const HwConfig& c) {
  std::pair<uint64_t, const char*> parts[] = {
      {ray_slots(c) * kRayContextBytes,
       c.rt.mode == TraversalMode::Treelet ? "treelet_queues.max_rays"
       : c.sort.key != SortKey::None       ? "rt.count * rt.warps * rt.warp_size + sort.buffer_rays"
                                           : "rt.count * rt.warps * rt.warp_size"},
      {c.sort.key == SortKey::Hash ? c.sort.bins * kSortBinBytes : 0, "sort.bins"},
      {c.rt_units * kRtUnitBytes, "rt.count"},
      {c.shader.model == ShaderModel::Simt ? c.rt_units * c.shader.warps * kShaderWarpBytes : 0,
       "shader.warps (each of rt.count SMs)"}};
  SimHostMemory memory;
  uint64_t largest = 0;
  for (const MemoryLevelConfig& level : c.memory) {
    uint32_t n = level_instances(level, c.rt_units);
    uint64_t bytes = n * cache_host_bytes(level.cache);
    memory.bytes += bytes;
    if (bytes <= largest) continue;
    largest = bytes;
    memory.largest = fmt::format("memory.{}.size_bytes{}", level.name,
                                 n > 1 ? fmt::format(" (each of {} instances)", n) : "");
  }
  for (const auto& [bytes, key] : parts) {
    memory.bytes += bytes;
    if (bytes <= largest) continue;
    largest = bytes;
    memory.largest = key;
  }
  return memory;
}

std::string hw_config_problem(const HwConfig& c) {
  auto section = [](const char* name, const std::string& problem) {
    return problem.empty() ? problem : fmt::format("[{}] {}", name, problem);
  };
  std::string p = section("rt", rt_core_config_problem(c.rt));
  if (p.empty()) p = hierarchy_problem(c.memory);
  if (p.empty()) p = section("dram", dram_config_problem(c.dram));
  if (p.empty() && c.dram_model == DramModel::Banked)
    p = section("dram", banked_dram_config_problem(c.banked_dram));
  if (p.empty()) p = section("dispatch", dispatch_config_problem(c.dispatch));
  if (p.empty()) p = section("treelet_queues", treelet_queue_config_problem(c.treelet_queues));
  if (p.empty()) p = section("sort", sort_config_problem(c.sort));
  if (p.empty() && c.sort.key != SortKey::None && c.rt.mode == TraversalMode::Treelet)
    p = "[sort] a sorting unit feeds depth_first or packet units; treelet queues group rays "
        "themselves (set sort.key = \"none\")";
  if (p.empty() && c.sort.key != SortKey::None && c.sort.buffer_rays < c.rt.warp_size)
    p = fmt::format("[sort] buffer_rays ({}) must hold at least a warp (rt.warp_size = {})",
                    c.sort.buffer_rays, c.rt.warp_size);
  if (p.empty()) p = section("bvh", validate(c.bvh));
  if (p.empty()) p = section("shader", shader_config_problem(c.shader));
  if (p.empty() && c.shader.model != ShaderModel::None &&
      (c.rt.mode == TraversalMode::Treelet || c.rt.refill == Refill::Slot))
    p = "[shader] model = \"simt\" needs whole warps: rt.mode = \"depth_first\" with rt.refill "
        "= \"warp\", or \"packet\" (treelet queues and slot refill split a warp's rays)";
  const RayBufferConfig& buffer = c.treelet_queues.buffer;
  uint32_t state = ray_state_bytes(c.rt.stack);
  if (p.empty() && buffer.place == RayBufferPlace::Sram &&
      ray_buffer_capacity(buffer, state, c.treelet_queues.max_rays) == 0)
    p = fmt::format(
        "[treelet_queues] buffer_bytes ({}) holds no ray state: one takes {} bytes (32 + 16 + 8 "
        "+ rt.stack.entries * rt.stack.entry_bytes)",
        buffer.bytes, state);
  uint64_t slots = uint64_t(c.rt_units) * c.rt.warps * c.rt.warp_size;
  if (p.empty() && c.rt.mode == TraversalMode::Treelet && c.treelet_queues.max_rays < slots)
    p = fmt::format(
        "[treelet_queues] max_rays ({}) must be at least the ray slots of all units "
        "(rt.count * rt.warps * rt.warp_size = {})",
        c.treelet_queues.max_rays, slots);
  return p;
}

HwConfig load_hw_config(const std::string& path, const std::vector<std::string>& overrides) {
  ConfigReadContext ctx;
  HwConfig config = read_keys(path, overrides, ctx);
  std::string problem = hw_config_problem(config);
  if (!problem.empty())
    throw_input_error(config_culprit(path, overrides, hw_config_problem), "", ctx.shown(problem));
  SimHostMemory memory = sim_host_memory(config);
  if (memory.bytes > available_memory_bytes()) {
    auto too_big = [](const HwConfig& c) {
      return std::string(sim_host_memory(c).bytes > available_memory_bytes() ? "too big" : "");
    };
    require_memory(memory.bytes, config_culprit(path, overrides, too_big),
                   "simulating this machine", "lower " + ctx.shown(memory.largest));
  }
  return config;
}

std::string config_culprit(const std::string& path, const std::vector<std::string>& overrides,
                           const std::function<std::string(const HwConfig&)>& problem_of) {
  ConfigReadContext alone, both;
  std::string file = path.empty() ? "(defaults)" : path;
  if (overrides.empty()) return file;
  try {
    if (!problem_of(read_keys(path, {}, alone)).empty()) return file;
  } catch (const InputError&) {
    // the file alone does not read (a value that an override replaces): blame the overrides
  }
  read_keys(path, overrides, both);
  return both.set_places();
}

std::vector<HwConfigKey> hw_config_keys() {
  ConfigReadContext ctx = resolve(HwConfig{});
  std::vector<HwConfigKey> keys;
  for (const ConfigKeyDoc& d : ctx.docs)
    keys.push_back({d.key, d.type, d.default_value, d.unit, d.description});
  return keys;
}

std::string resolved_toml(const HwConfig& config) {
  ConfigReadContext ctx = resolve(config);
  std::ostringstream out;
  out << "# Resolved rtsim hardware config: every key, defaults filled in.\n";
  std::string section;
  for (size_t i = 0; i < ctx.values.size(); ++i) {
    const auto& [key, value] = ctx.values[i];
    size_t dot = key.rfind('.');
    std::string key_section = dot == std::string::npos ? "" : key.substr(0, dot);
    if (key_section != section) {
      section = key_section;
      out << "\n[" << section << "]\n";
    }
    const ConfigKeyDoc& doc = ctx.docs[i];
    out << key.substr(dot == std::string::npos ? 0 : dot + 1) << " = " << toml_literal(value)
        << "  # " << (doc.unit.empty() ? "" : doc.unit + ": ") << doc.description << "\n";
  }
  return out.str();
}

nlohmann::ordered_json resolved_json(const HwConfig& config) {
  ConfigReadContext ctx = resolve(config);
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& [key, value] : ctx.values) {
    nlohmann::ordered_json* node = &out;
    size_t start = 0;
    for (size_t dot = key.find('.'); dot != std::string::npos; dot = key.find('.', start)) {
      node = &(*node)[key.substr(start, dot - start)];
      start = dot + 1;
    }
    (*node)[key.substr(start)] = value;
  }
  return out;
}

}  // namespace rtsim
