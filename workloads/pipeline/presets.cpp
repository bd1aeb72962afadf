// Pass budgets by preset. "pica-pica" follows SEED's talk ("Stochastic all the things",
// Stachowiak 2018): primary rays at full resolution, one shadow ray per pixel per light,
// reflections and reflected shadows at half resolution (1/4 ray per pixel each), diffuse GI
// from surfels with 250k rays per frame, AO at half resolution, refraction where materials are
// transmissive and translucency at half resolution.
#include <stdexcept>

#include "workloads/pipeline/spec.h"

namespace rtsim::pipeline {

PassSpecs preset_passes(const std::string& name) {
  PassSpecs p;
  if (name == "pica-pica") {
    p.shadow.resolution_scale = 1.0f;
    p.reflection.resolution_scale = 0.5f;
    p.ao.resolution_scale = 0.5f;
    p.refraction.resolution_scale = 1.0f;
    p.translucency.resolution_scale = 0.5f;
    p.gi.budget = 250000;
    return p;
  }
  if (name == "full-rate") {
    p.reflection.resolution_scale = 1.0f;
    p.ao.resolution_scale = 1.0f;
    p.translucency.resolution_scale = 1.0f;
    p.gi.budget = 1000000;
    return p;
  }
  throw std::invalid_argument("unknown preset '" + name + "'");
}

std::vector<std::string> preset_names() {
  return {"pica-pica", "full-rate"};
}

}  // namespace rtsim::pipeline
