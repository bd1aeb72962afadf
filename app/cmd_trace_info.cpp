// rtsim trace-info FILE: a ray stream's header and per-type counts, after checking every chunk.
#include <fmt/core.h>

#include "app/commands.h"
#include "traces/stream.h"

namespace rtsim::app {
namespace {

void print_instance_settings(const InstanceSettings& s) {
  fmt::print("instances    {} masked, {} moving ({} motions over the frames)\n", s.masks.size(),
             s.moving.size(), s.motions.size());
  std::string masks;
  for (int t = 0; t < kRayTypeCount; ++t)
    if (s.ray_masks[size_t(t)] != kAllInstances)
      masks += fmt::format("{}{} 0x{:02x}", masks.empty() ? "" : ", ", ray_type_name(RayType(t)),
                           s.ray_masks[size_t(t)]);
  fmt::print("ray masks    {}\n",
             masks.empty() ? "every type sees every instance" : masks + " (the others 0xff)");
}

}  // namespace

void add_trace_info_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("trace-info", "Print a ray stream's header and ray counts");
  auto path = std::make_shared<std::string>();
  auto header_only = std::make_shared<bool>(false);
  cmd->add_option("stream", *path, "Ray stream file (.rays)")->required();
  cmd->add_flag("--header-only", *header_only, "Skip reading and checking the rays");
  cmd->callback([path, header_only, &exit_code] {
    RayStreamReader reader(*path);
    const StreamHeader& h = reader.header();
    if (!*header_only) {
      Ray ray;
      while (reader.next(ray)) {
      }
    }
    fmt::print("file         {}\n", *path);
    fmt::print("version      {}\n", h.version);
    fmt::print("scene        {}\n", h.scene_source);
    fmt::print("fingerprint  {:016x}\n", h.scene_fingerprint);
    fmt::print("workload     {}\n", h.workload);
    fmt::print("generator    {}\n", h.generator);
    fmt::print("seed         {}\n", h.seed);
    fmt::print("frames       {}\n", h.frame_count);
    fmt::print("resolution   {}x{}\n", h.width, h.height);
    fmt::print("chunk rays   {}\n", h.chunk_rays);
    if (!h.instances.empty()) print_instance_settings(h.instances);
    fmt::print("rays         {}{}\n", h.total_rays(),
               *header_only ? " (not checked)" : " (all chunks checked)");
    for (int t = 0; t < kRayTypeCount; ++t)
      fmt::print("  {:<17}{}\n", ray_type_name(RayType(t)), h.counts[t]);
    exit_code = 0;
  });
}

}  // namespace rtsim::app
