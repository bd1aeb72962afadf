// rtsim curve STREAM --config HW.toml [--level NAME] --size 256K..64M: a cache level's (by
// default the level above DRAM's) miss rate and the bytes it sends below (DRAM bytes for the
// last level) per ray at every capacity (and associativity) from one functional pass over the
// stream (model/fidelity/CURVE.md), its knee, and with --simulate the full model's cycles at a few
// capacities, the others interpolated. --l2 A..B is --size for the level above DRAM. With -o DIR
// it writes curve.{json,csv,md}, the chart curve.png and config.toml. With --l1 A,B,C: one pass
// and curve per size of the first level (the curved level's references depend on it), each in
// DIR/l1-SIZE/, and the family in curve-l1.{md,png}.
#include <algorithm>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <fmt/ranges.h>

#include "app/commands.h"
#include "model/config/hw_config.h"
#include "model/fidelity/cache_curve.h"
#include "model/sc/sim_report.h"
#include "reports/charts.h"
#include "reports/curve_report.h"
#include "reports/phase_progress.h"
#include "traces/byte_size.h"
#include "traces/error.h"
#include "traces/memory_plan.h"
#include "traces/output_file.h"
#include "traces/stream.h"
#include "workloads/scene.h"

namespace rtsim::app {
namespace {

constexpr const char* kDefaultSizes = "256K..64M";

struct CurveOptions {
  std::string stream, config, output, scene, level, size, l2, simulate, l1;
  std::vector<std::string> sets;
  std::vector<uint32_t> ways;
  uint32_t sample_rate = 1;
  bool no_charts = false;
};

// A size (traces/byte_size.h) within the limits of the cache's size_bytes (`key`).
uint64_t parse_size(const std::string& text, const std::string& option, const char* key) {
  uint64_t value = parse_byte_size(text, "curve: " + option);
  if (value < kMinCacheBytes || value > kMaxCacheBytes)
    throw InputError(fmt::format("curve: {}: '{}' is out of range [{}, {}] (the limits of {})",
                                 option, text, byte_size_text(kMinCacheBytes),
                                 byte_size_text(kMaxCacheBytes), key));
  return value;
}

// "A..B": A, 2A, 4A, ... up to B; or "A,B,C".
std::vector<uint64_t> parse_sizes(const std::string& text, const std::string& option,
                                  const char* key) {
  std::vector<uint64_t> out;
  size_t range = text.find("..");
  if (range != std::string::npos) {
    uint64_t from = parse_size(text.substr(0, range), option, key);
    uint64_t to = parse_size(text.substr(range + 2), option, key);
    if (to < from) throw InputError(fmt::format("curve: {}: '{}' runs backwards", option, text));
    for (uint64_t c = from; c <= to; c *= 2) out.push_back(c);
    return out;
  }
  for (size_t at = 0; at <= text.size();) {
    size_t comma = std::min(text.find(',', at), text.size());
    out.push_back(parse_size(text.substr(at, comma - at), option, key));
    at = comma + 1;
  }
  return out;
}

// The capacities asked for: --size, or its alias --l2, or the default.
std::string sizes_option(const CurveOptions& o) {
  if (!o.l2.empty()) return "--l2 " + o.l2;
  return "--size " + (o.size.empty() ? std::string(kDefaultSizes) : o.size);
}

// The options that make the request, as its errors name them.
std::string request_options(const CurveOptions& o) {
  std::string text = (o.level.empty() ? "" : "--level " + o.level + " ") + sizes_option(o);
  if (!o.ways.empty()) text += fmt::format(" --ways {}", fmt::join(o.ways, ","));
  if (!o.simulate.empty()) text += " --simulate " + o.simulate;
  if (o.sample_rate > 1) text += fmt::format(" --sample-rate {}", o.sample_rate);
  return text;
}

struct CurveInputs {
  const CurveOptions& options;
  const std::string& scene_source;
  BvhView image;
  std::vector<uint64_t> simulate;  // capacities the full model runs at (besides the knee's)
};

// One pass over the stream on `config`, the full model at the chosen points, and the curve as
// JSON (rtsim.curve/1).
nlohmann::ordered_json curve_on(const HwConfig& config, const CurveRequest& request,
                                const CurveInputs& in) {
  const CurveOptions& o = in.options;
  uint32_t index = curve_level(config, request);
  const MemoryLevelConfig& level = config.memory[index];
  fmt::print(stderr,
             "curve: one pass, memory.{} {} bytes: memory.{} at {} capacities x {} "
             "associativities ({})\n",
             first_level(config).name, first_level(config).cache.size_bytes, level.name,
             request.capacities.size(), request.ways.size(),
             o.sample_rate > 1
                 ? fmt::format("miniature caches, 1 line in {}", o.sample_rate)
                 : std::string(level.fill == LevelFill::Victim ? "a cache per point: a victim level"
                                                               : "LRU stacks per set"));
  CacheCurve curve = run_cache_curve(config, in.image, o.stream, request);
  fmt::print(stderr,
             "curve: pass over {} rays done in {:.2f} s CPU ({} reads, {} writes, {} victim "
             "fills at memory.{})\n",
             curve.rays, curve.cpu_seconds, curve.reads, curve.writes, curve.fills, level.name);

  std::vector<size_t> first;  // the points of the first associativity: the ones simulated
  for (size_t i = 0; i < curve.points.size(); ++i)
    if (curve.points[i].ways == request.ways.front()) first.push_back(i);
  std::vector<size_t> runs;
  if (o.simulate == "knee") {
    auto k =
        size_t(std::find(first.begin(), first.end(), curve_knee(curve, first)) - first.begin());
    for (size_t i = k > 0 ? k - 1 : 0; i <= std::min(k + 1, first.size() - 1); ++i)
      runs.push_back(first[i]);
  }
  for (size_t i : first)
    if (std::count(in.simulate.begin(), in.simulate.end(), curve.points[i].capacity))
      runs.push_back(i);
  for (size_t n = 0; n < runs.size(); ++n) {
    CurvePoint& p = curve.points[runs[n]];
    fmt::print(stderr, "curve: full model at {} bytes, {} ways ({} of {})\n", p.capacity, p.ways,
               n + 1, runs.size());
    p.cycle_run = run_cycle_point(config, in.image, o.stream, index, p.capacity, p.ways);
    p.has_cycle_run = true;
  }
  fill_cycles(curve, first);

  nlohmann::ordered_json context = {{"stream", o.stream},
                                    {"scene", in.scene_source},
                                    {"rays", curve.rays},
                                    {"config", config.name},
                                    {"config_file", o.config},
                                    {"sets", o.sets},
                                    {"level", level.name},
                                    {"scope", scope_name(level)},
                                    {"fill", level.fill == LevelFill::Victim ? "victim" : "miss"},
                                    {"above_dram", index + 1 == config.memory.size()},
                                    {"instances", curve.instances},
                                    {"slices", level.slices},
                                    {"line_bytes", level.cache.line_bytes},
                                    {"first_level", first_level(config).name},
                                    {"first_level_bytes", first_level(config).cache.size_bytes}};
  return reports::curve_json(curve, context);
}

// curve_chart.py OUTDIR CURVE.json...: one curve's chart, or the family's; the exit code.
int draw(const std::vector<std::string>& args) {
  return reports::chart_exit_code(reports::run_chart_script("curve_chart.py", args));
}

// The exit code of its chart.
int write_curve(const std::string& dir, const nlohmann::ordered_json& doc, const HwConfig& config,
                bool charts) {
  write_file_atomic(dir + "/curve.json", doc.dump(2) + "\n");
  write_file_atomic(dir + "/curve.csv", reports::curve_csv(doc));
  write_file_atomic(dir + "/curve.md", reports::curve_markdown(doc));
  write_file_atomic(dir + "/config.toml", resolved_toml(config));
  return charts ? draw({dir, dir + "/curve.json"}) : 0;
}

int run_curve(const CurveOptions& o) {
  HwConfig config = load_hw_config(o.config, o.sets);
  std::string problem = curve_config_problem(config);
  if (!problem.empty())
    throw InputError(fmt::format("curve: {}: {}",
                                 config_culprit(o.config, o.sets, curve_config_problem), problem));
  if (!o.l2.empty() && !o.size.empty())
    throw InputError("curve: --l2 and --size: give one (--l2 is --size for the level above DRAM)");
  CurveRequest request;
  request.level = o.level;
  uint32_t index = curve_level(config, request);
  const MemoryLevelConfig& level = config.memory[index];
  if (!o.l2.empty() && index + 1 != config.memory.size())
    throw InputError(fmt::format(
        "curve: --l2 sizes the level above DRAM (memory.{}); give --level {}'s sizes with --size",
        last_level(config).name, level.name));
  if (!o.l1.empty() && index == 0)
    throw InputError(fmt::format(
        "curve: --l1 sizes memory.{}, the level the curve is of: use --size", level.name));
  std::string key = "memory." + level.name + ".size_bytes";
  std::string sizes = sizes_option(o);
  size_t space = sizes.find(' ');
  request.capacities = parse_sizes(sizes.substr(space + 1), sizes.substr(0, space), key.c_str());
  request.ways = o.ways.empty() ? std::vector<uint32_t>{level.cache.ways} : o.ways;
  request.sample_rate = o.sample_rate;
  std::vector<uint64_t> simulate;
  if (!o.simulate.empty() && o.simulate != "knee")
    simulate = parse_sizes(o.simulate, "--simulate", key.c_str());
  // Whole sets in every slice at every associativity: a multiple of line x slices x each way
  // count (with 6 slices, 16M is not), rounded down, and said so.
  uint64_t whole = uint64_t(level.cache.line_bytes) * level.slices;
  for (uint32_t w : request.ways)
    whole = std::lcm(whole, uint64_t(level.cache.line_bytes) * level.slices * w);
  for (auto* list : {&request.capacities, &simulate})
    for (uint64_t& c : *list) {
      if (c % whole == 0 || c < whole) continue;
      fmt::print(stderr, "curve: {} bytes is {} bytes in whole sets of memory.{}'s {} slices\n", c,
                 c / whole * whole, level.name, level.slices);
      c = c / whole * whole;
    }
  for (uint64_t c : simulate) request.capacities.push_back(c);  // simulated points are points
  std::sort(request.capacities.begin(), request.capacities.end());
  request.capacities.erase(std::unique(request.capacities.begin(), request.capacities.end()),
                           request.capacities.end());
  problem = curve_request_problem(config, request);
  if (!problem.empty()) throw InputError(fmt::format("curve: {}: {}", request_options(o), problem));
  std::vector<HwConfig> configs;  // one per L1 size
  std::string first_key = "memory." + first_level(config).name + ".size_bytes";
  for (uint64_t size : o.l1.empty() ? std::vector<uint64_t>{first_level(config).cache.size_bytes}
                                    : parse_sizes(o.l1, "--l1", first_key.c_str())) {
    HwConfig c = config;
    first_level(c).cache.size_bytes = size;
    problem = cache_config_problem(first_level(c).cache);
    if (!problem.empty()) throw InputError(fmt::format("curve: --l1: {} bytes: {}", size, problem));
    configs.push_back(c);
  }
  uint64_t need = 0;
  for (const HwConfig& c : configs)
    need = std::max(need, curve_host_bytes(c, request, !o.simulate.empty()));
  require_memory(need, "curve: " + request_options(o) + (o.l1.empty() ? "" : " --l1 " + o.l1),
                 "the curve's cache model",
                 "ask for fewer or smaller capacities, or sample them (--sample-rate)");
  bool family = !o.l1.empty();
  if (!o.output.empty()) {
    create_output_folder(o.output);
    lock_output_folder(o.output, "rtsim curve");
  }
  RayStreamReader reader(o.stream);
  Scene scene = load_stream_scene(o.stream, reader.header(), o.scene);
  TwoLevelBvh bvh = reports::build_scene_bvh(scene, config.bvh, false);
  CurveInputs in{o, reader.header().scene_source, BvhView(bvh), simulate};

  std::vector<nlohmann::ordered_json> docs;
  std::vector<std::string> files;  // their curve.json
  int exit_code = 0;
  for (const HwConfig& c : configs) {
    nlohmann::ordered_json& doc = docs.emplace_back(curve_on(c, request, in));
    if (family) fmt::print("L1 {}:\n", reports::size_text(first_level(c).cache.size_bytes, true));
    fmt::print("{}", reports::curve_table(doc, false));
    if (family) fmt::print("\n");
    if (o.output.empty()) continue;
    std::string dir =
        family ? o.output + "/l1-" + reports::size_text(first_level(c).cache.size_bytes, true)
               : o.output;
    if (family) create_output_folder(dir);
    exit_code = std::max(exit_code, write_curve(dir, doc, c, !o.no_charts));
    files.push_back(dir + "/curve.json");
  }
  if (o.output.empty()) return 0;
  if (family) {
    write_file_atomic(o.output + "/curve-l1.md", reports::curve_family_markdown(docs));
    write_file_atomic(o.output + "/config.toml", resolved_toml(config));
    if (!o.no_charts) {
      files.insert(files.begin(), o.output);
      exit_code = std::max(exit_code, draw(files));
    }
  }
  fmt::print("\nresults in {}\n", o.output);
  return exit_code;
}

}  // namespace

void add_curve_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "curve",
      "A cache level's miss rate and DRAM bytes (bytes below) per ray at every capacity from "
      "one functional pass");
  auto o = std::make_shared<CurveOptions>();
  cmd->add_option("stream", o->stream, "Ray stream (.rays)")->required();
  cmd->add_option("--config", o->config, "Hardware config: " + kConfigForms);
  cmd->add_option("--set", o->sets, "Override a config key")->allow_extra_args(false);
  cmd->add_option("--scene", o->scene, "Scene file or built-in (default: stream header)");
  cmd->add_option("--level", o->level,
                  "The cache level to curve, by name (default: the level above DRAM)");
  cmd->add_option("--size", o->size,
                  "Its capacities: A..B (A, 2A, 4A, ... B) or A,B,C (K, M, G; default " +
                      std::string(kDefaultSizes) + ")");
  cmd->add_option("--l2", o->l2, "--size for the level above DRAM (the L2 of two levels)");
  cmd->add_option("--l1", o->l1,
                  "Sizes of the first level (per RT unit; A..B or A,B,C): one pass and curve "
                  "each, in DIR/l1-SIZE/, the family in curve-l1.md and .png (default: the "
                  "config's)");
  cmd->add_option("--ways", o->ways, "The level's associativities (default: the config's)")
      ->delimiter(',')
      ->check(CLI::Range(1, 254));
  cmd->add_option("--sample-rate", o->sample_rate,
                  "1: exact LRU stacks; R: miniature caches of 1 line in R (with 95% intervals)")
      ->check(CLI::Range(1, 4096))
      ->capture_default_str();
  cmd->add_option("--simulate", o->simulate,
                  "Run the full model at these capacities (A,B or A..B), or at 'knee' and its "
                  "two neighbours; the other points' cycles are interpolated");
  cmd->add_option("-o,--output", o->output, "Folder for curve.json, .csv, .md, .png");
  cmd->add_flag("--no-charts", o->no_charts, "Skip the chart");
  cmd->callback([o, &exit_code] { exit_code = run_curve(*o); });
}

}  // namespace rtsim::app
