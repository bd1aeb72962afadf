#include "reports/phase_progress.h"

#include <unistd.h>

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

BvhImage build_bvh_with_progress(const TriangleMesh& mesh, const BvhConfig& config, bool quiet) {
  if (quiet) return build_bvh_image(mesh, config);
  fmt::print(stderr, "bvh: building {} over {} triangles\n", describe(config),
             mesh.triangles.size());
  double start = wall_seconds();
  // Large builds take seconds a step: say each as it ends.
  BvhBuildStep step;
  if (mesh.triangles.size() >= kBvhStepTriangles)
    step = [](const char* name, double seconds) {
      fmt::print(stderr, "bvh:   {} in {:.1f} s\n", name, seconds);
    };
  BvhImage image = build_bvh_image(mesh, config, step);
  fmt::print(stderr, "bvh: {} nodes, {:.2f} MiB ({:.1f} B a triangle), built in {:.1f} s\n",
             image.node_count, image.total_bytes() / 1048576.0,
             double(image.total_bytes()) / double(mesh.triangles.size()), wall_seconds() - start);
  return image;
}

}  // namespace rtsim::reports
