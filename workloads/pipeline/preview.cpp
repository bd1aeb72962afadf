#include "workloads/pipeline/preview.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "traces/output_file.h"
#include "workloads/pipeline/image_io.h"
#include "workloads/pipeline/preview_filter.h"
#include "workloads/pipeline/sampling.h"
#include "workloads/pipeline/shading.h"

namespace rtsim::pipeline {
namespace {

// For a pass on a grid of `scale`, the record index of each cell (-1: none).
template <typename SampleOf>
std::vector<int64_t> records_by_cell(const GBuffer& g, float scale, size_t count,
                                     SampleOf sample_of) {
  std::vector<int64_t> cells(GBuffer::cell_count(g.width, g.height, scale), -1);
  for (size_t r = 0; r < count; ++r) {
    uint32_t cell = GBuffer::cell_of(g.samples[sample_of(r)].pixel, g.width, g.height, scale);
    if (cells[cell] < 0) cells[cell] = int64_t(r);
  }
  return cells;
}

class FrameShader {
 public:
  FrameShader(const Pipeline& p, const FrameResults& f)
      : p_(p), f_(f), s_(p.scene()), surfels_(p.surfels()), coarse_(3.0f * surfels_.radius()) {
    surfels_.smooth_irradiance(3.0f);
    for (const Surfel& s : surfels_.surfels()) coarse_.add(s);
    bool emissive = false;
    for (const ShadingMaterial& m : s_.materials.materials) emissive |= m.emissive();
    unlit_ = s_.lights.empty() && !emissive && s_.sky == glm::vec3(0.0f);
    const PassSpecs& passes = p.spec().passes;
    const GBuffer& g = f.gbuffer;
    reflection_ = records_by_cell(g, passes.reflection.resolution_scale, f.reflection.rays.size(),
                                  [&](size_t r) { return f.reflection.rays[r].sample; });
    refraction_ = records_by_cell(g, passes.refraction.resolution_scale, f.refraction.rays.size(),
                                  [&](size_t r) { return f.refraction.rays[r].sample; });
    translucency_ =
        records_by_cell(g, passes.translucency.resolution_scale, f.translucency.samples.size(),
                        [&](size_t r) { return f.translucency.samples[r]; });
    if (passes.shadow.enabled && !s_.lights.empty())
      shadow_ = filter_on_surfaces(g, f.shadow.visibility, s_.lights.size(), 2);
    // AO visibility of each sample's cell, then filtered.
    std::vector<int64_t> ao_cells =
        records_by_cell(g, passes.ao.resolution_scale, f.ao.samples.size(),
                        [&](size_t r) { return f.ao.samples[r]; });
    ao_.assign(g.samples.size(), -1.0f);
    for (size_t i = 0; i < g.samples.size(); ++i)
      if (int64_t r = lookup(ao_cells, g.samples[i].pixel, passes.ao.resolution_scale); r >= 0)
        ao_[i] = f.ao.visibility[size_t(r)];
    ao_ = filter_on_surfaces(g, ao_, 1, 2);
    // Surfel GI of each sample, blurred in screen space as the talk applies surfels.
    gi_.assign(g.samples.size() * 3, -1.0f);
    for (size_t i = 0; i < g.samples.size(); ++i) {
      glm::vec3 e;
      if (g.samples[i].surface.hit() && irradiance(g.samples[i].surface, e))
        for (int k = 0; k < 3; ++k) gi_[i * 3 + size_t(k)] = e[k];
    }
    gi_ = filter_on_surfaces(g, gi_, 3, 12, 3);
  }

  glm::vec3 sample(size_t i) const {
    const GSample& gs = f_.gbuffer.samples[i];
    if (!gs.surface.hit()) return s_.sky;
    const PassSpecs& passes = p_.spec().passes;
    const ShadingMaterial& m = s_.materials.materials[gs.material];
    const float* vis = shadow_.empty() ? nullptr : &shadow_[i * s_.lights.size()];
    float ao = ao_[i] >= 0.0f ? 0.25f + 0.75f * ao_[i] : 1.0f;
    glm::vec3 gi = gi_[i * 3] >= 0.0f ? glm::vec3(gi_[i * 3], gi_[i * 3 + 1], gi_[i * 3 + 2])
                                      : glm::vec3(0.0f);
    glm::vec3 color = shade_surface(s_, gs.surface, vis) + diffuse_albedo(m) / kPi * gi * ao;
    // A scene with no light at all: a white ambient term, so the picture still shows it.
    if (unlit_)
      color += diffuse_albedo(m) * ao * std::max(0.2f, -glm::dot(gs.view, gs.surface.normal));
    if (int64_t r = lookup(translucency_, gs.pixel, passes.translucency.resolution_scale);
        r >= 0 && m.translucency > 0.0f)
      color += m.base_color * m.translucency * f_.translucency.radiance[size_t(r)];
    if (int64_t r = lookup(refraction_, gs.pixel, passes.refraction.resolution_scale);
        r >= 0 && m.transmission > 0.0f) {
      const Surface& hit = f_.refraction.rays[size_t(r)].last_hit;
      // A chain that ends on glass (max_depth reached) shows the sky it would reach.
      bool opaque = hit.hit() && s_.material_of(hit.prim).transmission <= 0.0f;
      glm::vec3 through = opaque ? secondary(hit, nullptr) : s_.sky;
      color = glm::mix(color, m.base_color * through, m.transmission);
    }
    int64_t r = lookup(reflection_, gs.pixel, passes.reflection.resolution_scale);
    if (r < 0 || !m.glossy(passes.reflection.max_roughness)) return color;
    const ReflectionRecord& rec = f_.reflection.rays[size_t(r)];
    glm::vec3 incoming = s_.sky;
    if (rec.hit.hit()) {
      const float* rvis = passes.reflected_shadow && !s_.lights.empty()
                              ? &f_.reflected_shadow.visibility[size_t(r) * s_.lights.size()]
                              : nullptr;
      incoming = secondary(rec.hit, rvis);
    }
    float cos_v = std::max(0.0f, glm::dot(-gs.view, gs.surface.normal));
    glm::vec3 f0 = glm::mix(glm::vec3(dielectric_f0(m.ior)), m.base_color, m.metalness);
    glm::vec3 fresnel = f0 + (glm::vec3(1.0f) - f0) * std::pow(1.0f - cos_v, 5.0f);
    if (m.layers > 1) fresnel = glm::max(fresnel, glm::vec3(schlick(dielectric_f0(m.ior), cos_v)));
    return color * (glm::vec3(1.0f) - fresnel) + fresnel * incoming;
  }

 private:
  int64_t lookup(const std::vector<int64_t>& cells, uint32_t pixel, float scale) const {
    return cells[GBuffer::cell_of(pixel, f_.gbuffer.width, f_.gbuffer.height, scale)];
  }

  // Light leaving a surface that a reflection or refraction ray found. Its own mirror or glass
  // lobes are not traced further: they show the sky instead.
  glm::vec3 secondary(const Surface& hit, const float* visibility) const {
    const ShadingMaterial& m = s_.material_of(hit.prim);
    return shade_surface(s_, hit, visibility) + indirect(hit) +
           s_.sky * m.base_color * std::min(1.0f, m.metalness + m.transmission);
  }

  bool irradiance(const Surface& s, glm::vec3& out) const {
    // Where one frame left a hole between surfels (later frames would fill it), look farther.
    return surfels_.irradiance(s.position, s.normal, out) ||
           coarse_.irradiance(s.position, s.normal, out);
  }

  glm::vec3 indirect(const Surface& s) const {
    glm::vec3 e;
    if (!irradiance(s, e)) return glm::vec3(0.0f);
    return diffuse_albedo(s_.material_of(s.prim)) / kPi * e;
  }

  const Pipeline& p_;
  const FrameResults& f_;
  const SceneContext& s_;
  std::vector<int64_t> reflection_, refraction_, translucency_;
  // Filtered, per G-buffer sample (x lights for shadow_, x 3 for gi_).
  std::vector<float> shadow_, ao_, gi_;
  SurfelCache surfels_;  // with smoothed irradiance
  SurfelCache coarse_;   // the same surfels, looked up three times as far
  bool unlit_ = false;
};

// Fills pixels that got no sample (irregular placement) from the nearest pixel that did.
void fill_holes(std::vector<glm::vec3>& image, std::vector<uint32_t>& weight, uint32_t width,
                uint32_t height) {
  std::vector<uint32_t> had = weight;
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      size_t p = size_t(y) * width + x;
      if (had[p]) continue;
      for (int radius = 1; radius <= 16 && !weight[p]; ++radius)
        for (int dy = -radius; dy <= radius && !weight[p]; ++dy)
          for (int dx = -radius; dx <= radius; ++dx) {
            int64_t nx = int64_t(x) + dx, ny = int64_t(y) + dy;
            if (nx < 0 || ny < 0 || nx >= int64_t(width) || ny >= int64_t(height)) continue;
            size_t q = size_t(ny) * width + size_t(nx);
            if (!had[q]) continue;
            image[p] = image[q];
            weight[p] = 1;
            break;
          }
    }
}

glm::vec3 heat(float t) {
  static const glm::vec3 kStops[5] = {{0.0f, 0.0f, 0.0f},
                                      {0.25f, 0.05f, 0.45f},
                                      {0.8f, 0.2f, 0.25f},
                                      {1.0f, 0.65f, 0.1f},
                                      {1.0f, 1.0f, 0.85f}};
  float x = std::clamp(t, 0.0f, 1.0f) * 4.0f;
  int i = std::min(3, int(x));
  return glm::mix(kStops[i], kStops[i + 1], x - float(i));
}

uint8_t to_byte(float v) {
  return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

}  // namespace

std::vector<glm::vec3> shade_frame(const Pipeline& pipeline, const FrameResults& frame) {
  const GBuffer& g = frame.gbuffer;
  std::vector<glm::vec3> image(size_t(g.width) * g.height, glm::vec3(0.0f));
  std::vector<uint32_t> weight(image.size(), 0);
  FrameShader shader(pipeline, frame);
  for (size_t i = 0; i < g.samples.size(); ++i) {
    image[g.samples[i].pixel] += shader.sample(i);
    weight[g.samples[i].pixel]++;
  }
  for (size_t p = 0; p < image.size(); ++p)
    if (weight[p] > 1) image[p] /= float(weight[p]);
  fill_holes(image, weight, g.width, g.height);
  return image;
}

std::vector<uint8_t> tone_map(const std::vector<glm::vec3>& radiance) {
  double log_sum = 0.0;
  size_t n = 0;
  for (const glm::vec3& c : radiance) {
    float lum = 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
    if (lum <= 0.0f) continue;
    log_sum += std::log(1e-4 + lum);
    ++n;
  }
  float exposure = n ? float(0.18 / std::exp(log_sum / double(n))) : 1.0f;
  std::vector<uint8_t> out(radiance.size() * 3);
  for (size_t p = 0; p < radiance.size(); ++p)
    for (int k = 0; k < 3; ++k) {
      float v = radiance[p][k] * exposure;
      v = v * (1.0f + v / 4.0f) / (1.0f + v);  // Reinhard with white point 2
      v = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
      out[p * 3 + size_t(k)] = to_byte(v);
    }
  return out;
}

void write_preview(const std::string& path, const Pipeline& pipeline, const FrameResults& frame) {
  write_png(path, frame.gbuffer.width, frame.gbuffer.height,
            tone_map(shade_frame(pipeline, frame)));
}

std::string density_image_path(const std::string& preview_path, const std::string& pass) {
  std::string stem = output_target(preview_path);
  auto dot = stem.find_last_of('.');
  auto slash = stem.find_last_of('/');
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash))
    stem = stem.substr(0, dot);
  return stem + ".density-" + pass + ".png";
}

std::vector<std::string> preview_files(const std::string& preview_path) {
  std::vector<std::string> files = {preview_path};
  if (!writes_regular_file(preview_path)) return files;
  for (int p = 0; p < kPassCount; ++p)
    files.push_back(density_image_path(preview_path, pass_name(PassId(p))));
  files.push_back(density_image_path(preview_path, "all"));
  return files;
}

std::vector<std::string> write_density_images(const std::string& preview_path, const RaySink& sink,
                                              uint32_t width, uint32_t height) {
  std::vector<std::string> written;
  if (!writes_regular_file(preview_path)) return written;
  std::vector<uint32_t> all(size_t(width) * height, 0);
  auto write = [&](const std::vector<uint32_t>& counts, const std::string& name) {
    uint32_t most = *std::max_element(counts.begin(), counts.end());
    // One colour per count, log scale.
    std::vector<glm::vec3> colour(size_t(most) + 1);
    for (uint32_t c = 0; c <= most; ++c)
      colour[c] = heat(most ? float(std::log1p(double(c)) / std::log1p(double(most))) : 0.0f);
    std::vector<uint8_t> rgb(counts.size() * 3);
    for (size_t p = 0; p < counts.size(); ++p)
      for (int k = 0; k < 3; ++k) rgb[p * 3 + size_t(k)] = to_byte(colour[counts[p]][k]);
    std::string path = density_image_path(preview_path, name);
    write_png(path, width, height, rgb);
    written.push_back(path);
  };
  for (int p = 0; p < kPassCount; ++p) {
    const auto& counts = sink.density(PassId(p));
    if (sink.count(PassId(p)) == 0 || counts.size() != all.size()) continue;
    for (size_t i = 0; i < all.size(); ++i) all[i] += counts[i];
    write(counts, pass_name(PassId(p)));
  }
  if (sink.total() > 0) write(all, "all");
  return written;
}

}  // namespace rtsim::pipeline
