// Alpha-tested test geometry (traces/alpha.h): layers of checker-masked quads before an opaque
// one, for the model's and the simulator's alpha tests.
#pragma once

#include <memory>

#include "tests/model/model_test_util.h"
#include "traces/alpha.h"

namespace rtsim::test {

// A 2x2 checker whose texels (0, 0) and (1, 1) are opaque.
inline std::shared_ptr<const AlphaMask> checker() {
  auto m = std::make_shared<AlphaMask>();
  m->name = "checker";
  m->width = m->height = 2;
  m->alpha = {255, 0, 0, 255};
  return m;
}

// `layers` checker-masked quads [0, 2]^2 at z = 0, -1, ... (texture coordinates x/2, y/2), then
// an opaque quad at z = -layers.
inline TriangleMesh layered(int layers) {
  TriangleMesh mesh;
  auto alpha = std::make_shared<TriangleAlpha>();
  alpha->masks = {checker()};
  for (int l = 0; l <= layers; ++l) {
    auto z = float(-l);
    test::add_triangle(mesh, {0, 0, z}, {2, 0, z}, {2, 2, z});
    test::add_triangle(mesh, {0, 0, z}, {2, 2, z}, {0, 2, z});
    alpha->mask_of.insert(alpha->mask_of.end(), 2, l < layers ? 0 : TriangleAlpha::kOpaque);
    alpha->uv.push_back({glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1)});
    alpha->uv.push_back({glm::vec2(0, 0), glm::vec2(1, 1), glm::vec2(0, 1)});
  }
  mesh.alpha = std::move(alpha);
  return mesh;
}

}  // namespace rtsim::test
