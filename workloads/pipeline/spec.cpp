// Every key of a workload spec is read here, once, with its default, unit and description.
#include "workloads/pipeline/spec.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "traces/error.h"
#include "traces/stream.h"
#include "traces/toml_text.h"
#include "workloads/pipeline/spec_reader.h"
#include "workloads/scene.h"

namespace rtsim::pipeline {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void check_view(const SpecReader& r, glm::vec3 position, glm::vec3 look_at, glm::vec3 up) {
  ViewProblem problem = view_problem(position, look_at, up);
  if (problem == ViewProblem::NoDirection)
    r.fail("look_at", "equals position: the camera has no view direction");
  if (problem == ViewProblem::NoUp)
    r.fail("up",
           "is parallel to the view direction (position to look_at): the image has no "
           "up; choose another up");
}

// A point or direction of the spec is one rtsim can trace (scene.h's range of scene points).
void check_point(const SpecReader& r, const char* key, const std::optional<glm::vec3>& p) {
  if (std::string problem = p ? point_problem(*p) : ""; !problem.empty()) r.fail(key, problem);
}

void check_direction(const SpecReader& r, const char* key, const glm::vec3& d) {
  if (std::string problem = direction_problem(d); !problem.empty()) r.fail(key, problem);
}

void read_camera(SpecReader& r, CameraSpec& c) {
  c.position = r.vec3_or_auto("position", "the scene file's camera, else fit to the scene bounds",
                              "scene units", "where the camera is");
  check_point(r, "position", c.position);
  c.look_at = r.vec3_or_auto("look_at", "the scene file's camera, else fit to the scene bounds",
                             "scene units", "the point the camera looks at");
  check_point(r, "look_at", c.look_at);
  c.up = r.vec3("up", c.up, "", "the up direction of the image");
  check_direction(r, "up", c.up);
  c.fov = float(r.real("fov", c.fov, "degrees", "vertical field of view", kMinFov, kMaxFov));
  c.jitter = r.boolean("jitter", c.jitter, "sub-pixel Halton jitter per frame, as TAA does");
  c.orbit = float(r.real("orbit", c.orbit, "degrees",
                         "angle swept about the up axis through look_at over all frames", -3600.0,
                         3600.0));
  for (SpecReader* k : r.sections("key",
                                  "camera path: the camera moves through these keys, "
                                  "evenly spread over the frames")) {
    CameraKey key;
    auto position =
        k->maybe_vec3("position", "scene units", "camera position at this key", "(required)");
    auto look_at =
        k->maybe_vec3("look_at", "scene units", "look-at point at this key", "(required)");
    if (k->documenting()) continue;
    if (!position || !look_at) k->fail("", "a camera key needs position and look_at");
    check_point(*k, "position", position);
    check_point(*k, "look_at", look_at);
    check_view(*k, *position, *look_at, c.up);
    c.keys.push_back({*position, *look_at});
  }
  if (!r.documenting() && c.position && c.look_at) check_view(r, *c.position, *c.look_at, c.up);
}

void read_samples(SpecReader& r, SampleSpec& s) {
  auto placement = r.text("placement", "regular",
                          "camera samples: one per pixel, or placed by an importance map "
                          "(Harada & Fujita 2014)",
                          {"regular", "importance"});
  s.placement = placement == "importance" ? Placement::Importance : Placement::Regular;
  s.edges =
      r.boolean("edges", s.edges, "importance: more samples at depth, normal and material edges");
  s.cost = r.boolean("cost", s.cost,
                     "importance: more samples where the last frame shot more rays per pixel");
  s.uniform_share = float(r.real("uniform_share", s.uniform_share, "fraction",
                                 "importance: share of samples spread uniformly", 0.0, 1.0));
  s.count = uint64_t(r.integer("count", 0, "samples", "camera samples per frame; 0: one per pixel",
                               0, int64_t(1) << 32));
}

void read_material(SpecReader& r, MaterialRule& m) {
  m.match = r.text("match", "", "glob (* ?) matched against object/group and material names");
  if (m.match.empty() && !r.documenting())
    r.fail("match", "a material rule needs a non-empty match pattern");
  m.base_color = r.maybe_vec3("base_color", "linear RGB", "albedo");
  auto f = [&](const char* key, const char* unit, const char* desc, double lo, double hi) {
    auto v = r.maybe_real(key, unit, desc, lo, hi);
    return v ? std::optional<float>(float(*v)) : std::nullopt;
  };
  m.roughness = f("roughness", "", "perceptual roughness; GGX alpha = roughness^2", 0.0, 1.0);
  m.metalness = f("metalness", "", "0 dielectric, 1 conductor", 0.0, 1.0);
  auto layers = r.maybe_real("layers", "", "1 + number of clear coats over the base", 1.0, 8.0);
  if (layers) {
    if (std::floor(*layers) != *layers) r.fail("layers", "expected an integer");
    m.layers = int(*layers);
  }
  m.coat_roughness =
      f("coat_roughness", "", "roughness of each clear coat (default 0.05)", 0.0, 1.0);
  m.transmission = f("transmission", "", "> 0: refractive (glass); refraction rays", 0.0, 1.0);
  m.ior = f("ior", "", "index of refraction", 1.0, 4.0);
  m.translucency =
      f("translucency", "", "> 0: light scatters through; translucency rays", 0.0, 1.0);
  m.emission = r.maybe_vec3("emission", "linear RGB radiance", "emitted radiance");
}

void read_instance_rule(SpecReader& r, InstanceRule& rule) {
  rule.match = r.text("match", "", "glob (* ?) matched against each instance's object name");
  if (rule.match.empty() && !r.documenting())
    r.fail("match", "an instance rule needs a non-empty match pattern");
  rule.where = r.where();
  auto mask = r.maybe_real("mask", "bits",
                           "visibility mask (1 to 255): rays whose type's inclusion mask shares "
                           "no bit with it pass the instance by",
                           1.0, 255.0, "255");
  if (mask) {
    if (std::floor(*mask) != *mask) r.fail("mask", "expected an integer");
    rule.mask = uint8_t(*mask);
  }
  rule.motion.axis = r.vec3("axis", rule.motion.axis, "",
                            "motion: the axis the keys' rotate turns about, through the "
                            "instance's origin");
  check_direction(r, "axis", rule.motion.axis);
  rule.motion.axis = glm::normalize(rule.motion.axis);
  for (SpecReader* k : r.sections("key",
                                  "motion: keys spread evenly over the frames, linear in "
                                  "between; the instance moves relative to where the scene "
                                  "places it")) {
    MotionKey key;
    key.translate = k->vec3("translate", key.translate, "scene units", "moved by");
    key.rotate =
        float(k->real("rotate", 0.0, "degrees", "turned about the axis", -36000.0, 36000.0));
    key.scale = float(k->real("scale", 1.0, "", "scaled uniformly about its origin", 1e-3, 1e3));
    rule.motion.keys.push_back(key);
  }
  if (!r.documenting() && !rule.mask && rule.motion.keys.empty())
    r.fail("", "an instance rule needs a mask or motion keys ([[instances.key]])");
}

void read_ray_masks(SpecReader& r, std::array<uint8_t, kRayTypeCount>& masks) {
  for (int t = 0; t < kRayTypeCount; ++t) {
    std::string type = ray_type_name(RayType(t));
    auto mask = r.integer(type, kAllInstances, "bits",
                          "inclusion mask of this type's rays: the instances whose mask shares "
                          "a bit with it are the ones they see",
                          1, 255);
    masks[size_t(t)] = uint8_t(mask);
  }
}

void read_alpha_test(SpecReader& r, std::array<bool, kRayTypeCount>& alpha_test) {
  for (int t = 0; t < kRayTypeCount; ++t)
    alpha_test[size_t(t)] =
        r.boolean(ray_type_name(RayType(t)), alpha_test[size_t(t)],
                  "this type's rays run the any-hit alpha test on alpha-tested triangles; "
                  "false: RAY_FLAG_FORCE_OPAQUE, masked triangles are solid");
}

void read_light(SpecReader& r, LightSpec& l) {
  auto type = r.text("type", "point", "kind of light", {"point", "spot", "directional", "sphere"});
  l.type = type == "spot"          ? LightType::Spot
           : type == "directional" ? LightType::Directional
           : type == "sphere"      ? LightType::Sphere
                                   : LightType::Point;
  l.position = r.vec3_or_auto("position", "centre of the bounds, 90% up", "scene units",
                              "point, spot, sphere: where the light is");
  check_point(r, "position", l.position);
  l.direction = r.vec3("direction", l.direction, "", "spot, directional: where the light shines");
  check_direction(r, "direction", l.direction);
  l.color = r.vec3("color", l.color, "linear RGB", "colour of the light");
  l.intensity = float(r.real("intensity", l.intensity, "W/sr (directional: W/m^2)",
                             "radiant intensity", 0.0, kInf));
  auto radius = r.real_or_auto("radius", "0.5% of the scene diagonal", "scene units",
                               "sphere: radius; gives soft shadows", 0.0, kInf);
  if (radius) l.radius = float(*radius);
  l.cone_angle = float(
      r.real("cone_angle", l.cone_angle, "degrees", "spot: half angle of the cone", 0.0, 180.0));
  l.angular_diameter = float(r.real("angular_diameter", l.angular_diameter, "degrees",
                                    "directional: > 0 gives soft (sun disk) shadows", 0.0, 90.0));
}

void read_rate(SpecReader& r, PassRate& p, const char* what) {
  p.enabled = r.boolean("enabled", p.enabled, what);
  p.resolution_scale = float(r.real("resolution_scale", p.resolution_scale, "fraction",
                                    "grid of this scale x the image; one camera sample per "
                                    "cell gets rays (1: every camera sample)",
                                    0.01, 1.0));
  p.rays_per_pixel = uint32_t(r.integer("rays_per_pixel", p.rays_per_pixel, "rays",
                                        "rays per chosen sample (shadow: per light)", 1, 1024));
}

void read_gi(SpecReader& r, GiSpec& g) {
  g.enabled = r.boolean("enabled", g.enabled, "diffuse GI rays from world-space surfels");
  g.budget = uint64_t(r.integer("budget", int64_t(g.budget), "rays", "GI rays per frame at most", 0,
                                int64_t(1) << 32));
  g.rays_per_surfel =
      uint32_t(r.integer("rays_per_surfel", g.rays_per_surfel, "rays",
                         "wanted per surfel per frame before the budget cap", 1, 65536));
  g.new_surfel_boost =
      float(r.real("new_surfel_boost", g.new_surfel_boost, "x",
                   "ray weight of surfels younger than new_surfel_frames", 1.0, 64.0));
  g.new_surfel_frames = uint32_t(r.integer("new_surfel_frames", g.new_surfel_frames, "frames",
                                           "how long a surfel counts as new", 0, 1000));
  g.tile = uint32_t(r.integer("tile", g.tile, "pixels", "surfel spawn tile size", 1, 256));
  g.coverage_stride =
      uint32_t(r.integer("coverage_stride", g.coverage_stride, "pixels",
                         "coverage is evaluated on every Nth pixel of a tile", 1, 256));
  g.coverage_threshold =
      float(r.real("coverage_threshold", g.coverage_threshold, "",
                   "tiles whose lowest coverage reaches this spawn nothing", 0.0, kInf));
  auto radius = r.real_or_auto("surfel_radius", "3/4 of a tile's footprint at the median depth",
                               "scene units", "surfel radius", 1e-30, kInf);
  if (radius) g.surfel_radius = float(*radius);
  g.max_surfels = uint32_t(r.integer("max_surfels", g.max_surfels, "surfels",
                                     "surfels kept at most", 1, int64_t(1) << 26));
  g.light_connections = r.boolean("light_connections", g.light_connections,
                                  "one shadow ray from each GI hit to a light");
}

void read_passes(SpecReader& r, PassSpecs& p) {
  read_rate(r.section("shadow", "shadow rays toward every light"), p.shadow, "shadow rays");
  SpecReader& refl = r.section("reflection", "GGX reflection rays");
  read_rate(refl, p.reflection, "reflection rays from glossy surfaces");
  p.reflection.max_roughness = float(refl.real("max_roughness", p.reflection.max_roughness, "",
                                               "rougher surfaces get no reflection ray", 0.0, 1.0));
  p.reflection.max_rerolls = uint32_t(refl.integer("max_rerolls", p.reflection.max_rerolls, "",
                                                   "new samples tried below the horizon", 0, 64));
  p.reflected_shadow = r.section("reflected_shadow", "shadow rays from reflection hits")
                           .boolean("enabled", p.reflected_shadow,
                                    "one shadow ray per light from each reflection hit");
  read_gi(r.section("gi", "diffuse global illumination"), p.gi);
  SpecReader& ao = r.section("ao", "ambient occlusion: short any-hit rays");
  read_rate(ao, p.ao, "AO rays");
  auto radius = ao.real_or_auto("radius", "2% of the scene diagonal", "scene units",
                                "length of AO rays", 0.0, kInf);
  if (radius) p.ao.radius = float(*radius);
  SpecReader& refr = r.section("refraction", "refraction rays through transmissive materials");
  read_rate(refr, p.refraction, "refraction rays");
  p.refraction.max_depth = uint32_t(refr.integer("max_depth", p.refraction.max_depth, "",
                                                 "interfaces crossed (2: in and out)", 1, 16));
  read_rate(r.section("translucency", "translucency rays inside translucent materials"),
            p.translucency, "translucency rays");
}

void read_root(SpecReader& r, WorkloadSpec& s, const std::string& stem) {
  s.name = r.text("name", stem, "workload name written into the stream; default: the file name");
  s.preset =
      r.text("preset", s.preset, "pass budgets the pass sections start from", preset_names());
  s.passes = preset_passes(s.preset);
  s.scene = r.text(
      "scene", "",
      "built-in scene (cornell, pica, grid:N, foliage:N, forest:N, city:N) or a scene file; a "
      "relative path is relative to this spec's folder");
  s.seed = uint64_t(r.integer("seed", int64_t(s.seed), "", "random seed", 0,
                              std::numeric_limits<int64_t>::max()));
  s.frames = uint32_t(r.integer("frames", s.frames, "frames", "frames to trace", 1, kMaxFrames));
  s.warmup_frames = uint32_t(
      r.integer("warmup_frames", s.warmup_frames, "frames",
                "frames run before frame 0 at its camera, writing no rays (surfels and the "
                "importance map warm up)",
                0, 100000));
  std::string res = r.text("resolution", "1920x1080", "image size WxH, pixels");
  if (!parse_resolution(res, s.width, s.height))
    r.fail("resolution", "expected WxH with positive integers, e.g. \"1920x1080\"");
  s.lights_from_emission = r.boolean("lights_from_emission", s.lights_from_emission,
                                     "emissive objects become spherical lights");
  s.sky = r.vec3("sky", s.sky, "linear RGB radiance", "radiance of rays that miss; 0: no sky");
  read_camera(r.section("camera", "the camera"), s.camera);
  read_samples(r.section("samples", "camera sample placement"), s.samples);
  for (SpecReader* m : r.sections("material", "material overrides by name pattern")) {
    s.materials.emplace_back();
    read_material(*m, s.materials.back());
  }
  for (SpecReader* i : r.sections("instances", "instance masks and motion by object name")) {
    s.instances.emplace_back();
    read_instance_rule(*i, s.instances.back());
  }
  read_ray_masks(r.section("ray_masks", "which instance masks each ray type sees"), s.ray_masks);
  read_alpha_test(r.section("alpha_test", "which ray types run the any-hit alpha test"),
                  s.passes.alpha_test);
  for (SpecReader* l : r.sections("light", "lights")) {
    s.lights.emplace_back();
    read_light(*l, s.lights.back());
  }
  read_passes(r, s.passes);
}

std::string folder_of(const std::string& path) {
  auto slash = path.find_last_of('/');
  return slash == std::string::npos ? "" : path.substr(0, slash + 1);
}

std::string stem_of(const std::string& path) {
  auto slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  auto dot = name.find_last_of('.');
  return dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
}

}  // namespace

bool parse_resolution(const std::string& text, uint32_t& width, uint32_t& height) {
  auto x = text.find('x');
  if (x == std::string::npos || x == 0 || x + 1 >= text.size()) return false;
  uint64_t w = 0, h = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    if (i == x) continue;
    if (text[i] < '0' || text[i] > '9') return false;
    uint64_t& v = i < x ? w : h;
    v = v * 10 + uint64_t(text[i] - '0');
    if (v > kMaxGridSide) return false;
  }
  if (w == 0 || h == 0) return false;
  width = uint32_t(w);
  height = uint32_t(h);
  return true;
}

WorkloadSpec parse_spec(const std::string& text, const std::string& file) {
  toml::table root = parse_toml(text, file);
  SpecReadContext ctx;
  ctx.file = file;
  WorkloadSpec spec;
  spec.file = file;
  ctx.readers.push_back(std::make_unique<SpecReader>(&root, "", ctx));
  SpecReader& r = *ctx.readers.back();
  read_root(r, spec, stem_of(file));
  ctx.finish();
  if (spec.scene.empty()) r.fail("scene", "missing: a spec needs a scene");
  if (!is_builtin_scene(spec.scene) && spec.scene[0] != '/')
    spec.scene = std::filesystem::path(folder_of(file) + spec.scene).lexically_normal().string();
  return spec;
}

WorkloadSpec read_spec(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw_input_error(path, "", "cannot read workload spec");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_spec(text.str(), path);
}

ViewProblem view_problem(const glm::vec3& position, const glm::vec3& look_at, const glm::vec3& up) {
  glm::vec3 view = look_at - position;
  if (glm::length(view) == 0.0f) return ViewProblem::NoDirection;
  if (glm::length(glm::cross(glm::normalize(view), glm::normalize(up))) < 1e-4f)
    return ViewProblem::NoUp;
  return ViewProblem::None;
}

WorkloadSpec default_spec_for_scene(const std::string& scene) {
  WorkloadSpec spec = parse_spec("scene = \"builtin:cornell\"\n", "default-spec.toml");
  spec.file.clear();
  spec.scene = scene;
  spec.name = std::filesystem::path(scene).stem().string();
  return spec;
}

std::vector<KeyDoc> spec_key_docs() {
  SpecReadContext ctx;
  ctx.documenting = true;
  ctx.readers.push_back(std::make_unique<SpecReader>(nullptr, "", ctx));
  WorkloadSpec spec;
  read_root(*ctx.readers.back(), spec, "");
  return ctx.docs;
}

}  // namespace rtsim::pipeline
