// rtsim hardcases -o OUT.rays: the numerical hard cases as a ray stream over the built-in
// scene `hardcases`, so `rtsim verify` and `rtsim sim` run them like any other workload.
#include <fmt/core.h>

#include "app/commands.h"
#include "reports/cli_options.h"
#include "traces/error.h"
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

uint64_t ray_count(const std::vector<hardcases::HardCase>& cases) {
  uint64_t total = 0;
  for (const auto& c : cases) total += c.rays.size();
  return total;
}

// The cases' rays before they are made: a fixed part and one in proportion to rays_per_case.
// They fit the stream's grid, one pixel each, and the memory available, or InputError.
void check_ray_count(size_t rays_per_case) {
  uint64_t fixed = ray_count(hardcases::make_hard_cases(0));
  uint64_t total = fixed + (ray_count(hardcases::make_hard_cases(1)) - fixed) * rays_per_case;
  if (total > uint64_t(kPixelsPerRow) * kMaxGridSide)
    throw InputError(fmt::format(
        "--rays-per-case {}: {} rays, more than a stream's largest grid for them ({} x {} "
        "pixels, one a ray) holds",
        rays_per_case, total, kPixelsPerRow, kMaxGridSide));
  reports::require_generated_ray_memory(total, "--rays-per-case");
}

void write_hardcases(const HardcasesOptions& options) {
  check_ray_count(options.rays_per_case);
  auto cases = hardcases::make_hard_cases(options.rays_per_case, options.seed);
  uint64_t total = ray_count(cases);

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
