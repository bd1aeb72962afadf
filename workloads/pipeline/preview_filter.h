// Denoising for the preview: one shadow ray per pixel per light and a quarter AO ray per pixel
// are noisy, and Pica Pica filters them spatially rather than shooting more (SVGF-style, with
// depth and normal edge-stopping). This is a plain 5x5 version for pictures only.
#pragma once

#include <cstddef>
#include <vector>

#include "workloads/pipeline/gbuffer.h"

namespace rtsim::pipeline {

// values holds `channels` numbers per G-buffer sample; negative means "none" and is left alone.
// Each other value becomes the mean of the values of the same channel at the first samples of
// every stride-th pixel within `radius`, among those on the same surface (normals within ~25
// degrees, depths within 5%).
std::vector<float> filter_on_surfaces(const GBuffer& g, const std::vector<float>& values,
                                      size_t channels, int radius, int stride = 1);

}  // namespace rtsim::pipeline
