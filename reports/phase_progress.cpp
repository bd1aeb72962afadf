#include "reports/phase_progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include <fmt/core.h>

#include "traces/host_clock.h"

namespace rtsim::reports {

std::function<void(uint32_t, uint32_t, pipeline::PassId)> trace_progress() {
  bool tty = isatty(fileno(stderr)) != 0;
  return [tty](uint32_t frame, uint32_t frames, pipeline::PassId pass) {
    const char* name = pipeline::pass_name(pass);
    if (!tty) {
      fmt::print(stderr, "trace: frame {}/{}: {}\n", frame + 1, frames, name);
      return;
    }
    double done = (double(frame) * pipeline::kPassCount + double(pass)) /
                  (double(frames) * pipeline::kPassCount);
    int filled = int(done * 30.0);
    fmt::print(stderr, "\r[{:<30}] {:3.0f}%  frame {}/{}  {:<16}", std::string(filled, '#'),
               100.0 * done, frame + 1, frames, name);
    if (frame + 1 == frames && pass == pipeline::PassId::Translucency)
      fmt::print(stderr, "\r{:<80}\r", "");
  };
}

constexpr size_t kBvhStepTriangles = 1000000;

namespace {

// Moving instances: what rebuilding the top level cost each frame (the first few, then the mean).
void print_top_builds(const std::vector<TopLevelBuild>& builds) {
  constexpr size_t kShown = 8;
  double nodes = 0, bytes = 0, seconds = 0;
  for (size_t f = 0; f < builds.size(); ++f) {
    const TopLevelBuild& b = builds[f];
    if (f < kShown)
      fmt::print(stderr, "bvh:   frame {} top level: {} nodes, {:.1f} KiB written, {:.2f} ms\n", f,
                 b.nodes, b.bytes / 1024.0, 1e3 * b.seconds);
    nodes += b.nodes;
    bytes += double(b.bytes);
    seconds += b.seconds;
  }
  double n = double(builds.size());
  fmt::print(stderr,
             "bvh:   a top level per frame, {} frames: {:.0f} nodes, {:.1f} KiB written and "
             "{:.2f} ms host time a frame (mean)\n",
             builds.size(), nodes / n, bytes / n / 1024.0, 1e3 * seconds / n);
}

}  // namespace

TwoLevelBvh build_scene_bvh(Scene& scene, const BvhConfig& config, bool quiet) {
  bool two_levels = wants_two_levels(config, scene.instanced) || !scene.instance_settings.empty();
  uint64_t triangles = two_levels && !scene.instanced.instances.empty()
                           ? scene.instanced.unique_triangles()
                           : scene.triangle_count();
  // Large builds take seconds a step: say each as it ends.
  BvhBuildStep step;
  if (!quiet && triangles >= kBvhStepTriangles)
    step = [](const char* name, double seconds) {
      fmt::print(stderr, "bvh:   {} in {:.1f} s\n", name, seconds);
    };
  if (!quiet && two_levels)
    fmt::print(stderr,
               "bvh: building two levels, {}, over {} instances of {} meshes ({} unique, {} "
               "instanced triangles)\n",
               describe(config), std::max<size_t>(scene.instanced.instances.size(), 1),
               std::max<size_t>(scene.instanced.meshes.size(), 1), triangles,
               std::max(scene.instanced.instanced_triangles(), triangles));
  else if (!quiet)
    fmt::print(stderr, "bvh: building {} over {} triangles\n", describe(config), triangles);
  double start = wall_seconds();
  if (!two_levels) flat_mesh(scene);
  if (!quiet && scene.instance_settings.animated())
    fmt::print(stderr, "bvh: {} instances move: a top level per frame, {} frames\n",
               scene.instance_settings.moving.size(), scene.instance_settings.frames);
  TwoLevelBvh bvh =
      build_scene_levels(scene.mesh, scene.instanced, config, step, scene.instance_settings);
  if (!quiet)
    fmt::print(stderr, "bvh: {}, built in {:.1f} s\n", bvh_summary(bvh), wall_seconds() - start);
  if (!quiet && bvh.top_builds.size() > 1) print_top_builds(bvh.top_builds);
  return bvh;
}

std::string bvh_summary(const TwoLevelBvh& bvh) {
  bool two_levels = !bvh.bottom.empty();
  return fmt::format("{} nodes{}, {:.2f} MiB ({:.1f} B a{} triangle)", bvh.node_count(),
                     two_levels ? fmt::format(" ({} in the TLAS)", bvh.top.node_count) : "",
                     bvh.total_bytes() / 1048576.0,
                     double(bvh.total_bytes()) / double(bvh.triangle_count()),
                     two_levels ? " unique" : "");
}

}  // namespace rtsim::reports
