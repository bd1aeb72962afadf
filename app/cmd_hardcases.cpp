// rtsim hardcases -o OUT.rays: the numerical hard cases as a ray stream over the built-in
// scene `hardcases`, so `rtsim verify` and `rtsim sim` run them like any other workload.
#include <fmt/core.h>

#include "app/commands.h"
#include "reports/cli_options.h"
#include "traces/stream.h"
#include "workloads/hardcases.h"

namespace rtsim::app {
namespace {

constexpr uint32_t kPixelsPerRow = 1024;

struct HardcasesOptions {
  std::string output;
  size_t rays_per_case = 2000;
  uint64_t seed = 1;
};

void write_hardcases(const HardcasesOptions& options) {
  auto cases = hardcases::make_hard_cases(options.rays_per_case, options.seed);
  size_t total = 0;
  for (const auto& c : cases) total += c.rays.size();

  StreamHeader header;
  header.scene_source = "builtin:hardcases";
  header.scene_fingerprint = load_scene("hardcases").fingerprint;
  header.workload = "hardcases";
  header.generator = "rtsim " RTSIM_VERSION;
  header.seed = options.seed;
  header.width = kPixelsPerRow;
  header.height = uint32_t((total + kPixelsPerRow - 1) / kPixelsPerRow);
  RayStreamWriter writer(options.output, header);
  uint32_t pixel = 0;
  for (const auto& c : cases) {
    for (Ray ray : c.rays) {
      ray.pixel = pixel++;  // one pixel per ray, so per-pixel buffers show each ray's cost
      ray.frame = 0;
      writer.write(ray);
    }
    fmt::print("  {:<28}{:>8} rays  {}\n", c.name, c.rays.size(), c.what);
  }
  writer.finish();
  fmt::print("wrote {} ({} rays in {} cases)\n", options.output, total, cases.size());
}

}  // namespace

void add_hardcases_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "hardcases",
      "Write the numerical hard cases (edges, vertices, grazing, offsets) as a stream");
  auto options = std::make_shared<HardcasesOptions>();
  cmd->add_option("-o,--output", options->output, "Ray stream to write (.rays)")->required();
  cmd->add_option("--rays-per-case", options->rays_per_case,
                  "Rays in each case's seeded random part")
      ->capture_default_str()
      ->check(CLI::Range(size_t(1), size_t(1) << 24));
  cmd->add_option("--seed", options->seed, "Seed of the random parts")
      ->check(reports::non_negative())
      ->capture_default_str();
  cmd->callback([options, &exit_code] {
    write_hardcases(*options);
    exit_code = 0;
  });
}

}  // namespace rtsim::app
