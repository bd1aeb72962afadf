#include "workloads/pipeline/summary.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace rtsim::pipeline {
namespace {

// Rays that met an alpha-tested candidate, and their share of all the rays.
std::string alpha_cell(uint64_t alpha_rays, uint64_t rays) {
  if (rays == 0) return "0";
  return fmt::format("{} ({:.1f}%)", alpha_rays, 100.0 * double(alpha_rays) / double(rays));
}

}  // namespace

std::string format_summary(const RunSummary& s) {
  double pixels = double(s.width) * s.height * std::max(1u, s.frames);
  std::string out = fmt::format(
      "workload {}: scene {} ({} triangles), {}x{}, {} frame{}, {} light{}, {} surfels\n",
      s.workload, s.scene_source, s.triangles, s.width, s.height, s.frames,
      s.frames == 1 ? "" : "s", s.lights, s.lights == 1 ? "" : "s", s.surfels);
  const glm::vec3 &p = s.camera_position, &l = s.camera_look_at;
  out += fmt::format("camera at [{:g}, {:g}, {:g}] looking at [{:g}, {:g}, {:g}] (frame 0)\n", p.x,
                     p.y, p.z, l.x, l.y, l.z);
  out += fmt::format("  {:<17}{:>12}{:>12}{:>14}{:>13}{:>20}  {}\n", "pass", "rays", "rays/pixel",
                     "budget/pixel", "1080p budget", "alpha-tested rays", "note");
  for (int p = 0; p < kPassCount; ++p) {
    const PassSummary& ps = s.passes[size_t(p)];
    std::string note;
    if (ps.rays == 0)
      note = "skipped: " + (ps.reason.empty() ? std::string("nothing to do") : ps.reason);
    else if (ps.frames_skipped > 0)
      note = fmt::format("skipped in {} of {} frames: {}", ps.frames_skipped, s.frames, ps.reason);
    double budget = double(ps.budget) * std::max(1u, s.frames) / pixels;
    out += fmt::format("  {:<17}{:>12}{:>12.4f}{:>14.4f}{:>13.4f}{:>20}  {}\n",
                       pass_name(PassId(p)), ps.rays, double(ps.rays) / pixels, budget,
                       ps.budget_per_pixel_1080p, alpha_cell(ps.alpha_rays, ps.rays), note);
  }
  out += fmt::format("  {:<17}{:>12}{:>12.4f}{:>14}{:>13}{:>20}\n", "total", s.total_rays(),
                     double(s.total_rays()) / pixels, "", "",
                     alpha_cell(s.total_alpha_rays(), s.total_rays()));
  return out;
}

std::string ray_mix_note(const RunSummary& s) {
  const double pixels = double(s.width) * s.height;
  std::string changed;
  for (int p = 0; p < kPassCount; ++p) {
    const PassSummary& ps = s.passes[size_t(p)];
    double here = double(ps.budget) / pixels, hd = ps.budget_per_pixel_1080p;
    if (hd <= 0.0 || std::abs(here / hd - 1.0) <= 0.05) continue;
    changed += fmt::format("{}{} {:.3g} against {:.3g} ({:.3g}x)", changed.empty() ? "" : ", ",
                           pass_name(PassId(p)), here, hd, here / hd);
  }
  if (changed.empty()) return "";
  const PassSummary& gi = s.passes[size_t(PassId::DiffuseGI)];
  uint64_t keeps =
      uint64_t(std::llround(double(gi.budget) * pixels / (double(kMixWidth) * kMixHeight)));
  return fmt::format(
      "ray mix at {}x{} is not the {}x{} one the budgets are set for: budget rays a pixel {}; the "
      "other passes are per pixel, as at {}x{}. Diffuse GI has a fixed budget a frame "
      "(gi.budget = {}); gi.budget = {} keeps the {}x{} mix",
      s.width, s.height, kMixWidth, kMixHeight, changed, kMixWidth, kMixHeight, gi.budget,
      std::max<uint64_t>(keeps, 1), kMixWidth, kMixHeight);
}

}  // namespace rtsim::pipeline
