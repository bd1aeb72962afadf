// Pictures that show what a stream holds. The preview shades the last traced frame from the
// passes' own results: Lambertian direct light with the shadow rays' visibility, GI from the
// surfels, darkened by AO, GGX reflections lit with the reflected-shadow rays, refraction and
// translucency, then auto-exposed and tone-mapped. Density images show how many rays of each
// pass landed on each pixel over the whole run (log scale, black = none).
#pragma once

#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "workloads/pipeline/pipeline.h"

namespace rtsim::pipeline {

// Linear radiance per pixel, rows top to bottom.
std::vector<glm::vec3> shade_frame(const Pipeline& pipeline, const FrameResults& frame);

// Auto exposure (log-average luminance to 0.18), Reinhard tone curve, sRGB, 8 bits.
std::vector<uint8_t> tone_map(const std::vector<glm::vec3>& radiance);

void write_preview(const std::string& path, const Pipeline& pipeline, const FrameResults& frame);

// PATH.png -> PATH.density-PASS.png ("all" for every pass together), beside the file PATH is
// (its links followed).
std::string density_image_path(const std::string& preview_path, const std::string& pass);

// Every file a preview at preview_path may write: itself and its density images. A preview that
// is a device, FIFO or socket (--preview /dev/null) gets the shaded picture only: the density
// images' names would put them in its folder (/dev).
std::vector<std::string> preview_files(const std::string& preview_path);

// Writes one density image per pass that shot rays, plus "all" (none beside a preview that is a
// device, FIFO or socket); returns the paths written.
std::vector<std::string> write_density_images(const std::string& preview_path, const RaySink& sink,
                                              uint32_t width, uint32_t height);

}  // namespace rtsim::pipeline
