// Layered materials (Pica Pica, after Weidlich & Wilkie 2007, "Arbitrarily Layered
// Micro-Facet Surfaces"): one reflection ray for the whole stack. A layer is chosen at random
// with probability proportional to an estimate of how much of it is visible: each clear coat
// reflects Schlick's Fresnel F_k(n.v) and passes 1 - F_k to the layers below. Since several
// layers can produce the same direction, the direction's density sums over all layers.
#pragma once

#include <glm/vec3.hpp>

#include "workloads/pipeline/materials.h"

namespace rtsim::pipeline {

constexpr int kMaxLayers = 8;

struct LayerStack {
  int count = 1;
  float alpha[kMaxLayers] = {};        // GGX alpha per layer, top coat first, base last
  float f0[kMaxLayers] = {};           // reflectance at normal incidence
  float probability[kMaxLayers] = {};  // chance of choosing each layer (sums to 1)
};

// The stack of m as seen from a view direction making cos_v with the normal.
LayerStack layer_stack(const ShadingMaterial& m, float cos_v);

// Index of the layer for a uniform random number u in [0, 1).
int choose_layer(const LayerStack& stack, float u);

// Density (solid angle) of reflected direction l for view v, both local with z the normal,
// summed over the layers weighted by their probabilities.
float stack_pdf(const LayerStack& stack, const glm::vec3& v, const glm::vec3& l);

}  // namespace rtsim::pipeline
