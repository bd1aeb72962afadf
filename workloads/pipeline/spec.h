// A workload spec: what `rtsim trace` renders (scene, materials, camera, lights, resolution)
// and how many rays each pass of the hybrid pipeline shoots. Read from TOML by read_spec();
// every key, its default, unit and description is declared once, in spec.cpp, and listed by
// spec_key_docs() (`rtsim trace --list-keys`, workloads/README.md).
#pragma once

#include <cstdint>
#include <array>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "traces/instance_settings.h"

namespace rtsim::pipeline {

// A material override applied to every triangle whose object (group) name or material name
// matches the glob pattern; unset fields keep the scene's value. Later rules win.
struct MaterialRule {
  std::string match;
  std::optional<glm::vec3> base_color;
  std::optional<float> roughness, metalness, coat_roughness, transmission, ior, translucency;
  std::optional<int> layers;
  std::optional<glm::vec3> emission;
};

// Settings for the instances whose object name matches the glob pattern (scenes of instances:
// glTF and OBJ nodes, forest:N, city:N): a visibility mask, and motion along keys over the
// frames. Later rules win.
struct InstanceRule {
  std::string match;
  std::string where;            // "line N" in the spec, for errors
  std::optional<uint8_t> mask;  // visibility mask; nullopt: keep (0xFF)
  Motion motion;                // no keys: stays where the scene places it
};

enum class LightType { Point, Spot, Directional, Sphere };

struct LightSpec {
  LightType type = LightType::Point;
  std::optional<glm::vec3> position;       // nullopt: auto (near the top of the scene bounds)
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // spot and directional: where the light points
  glm::vec3 color{1.0f};
  float intensity = 1.0f;         // W/sr for point/spot/sphere, W/m^2 for directional
  std::optional<float> radius;    // sphere; nullopt: auto (0.5% of the scene diagonal)
  float cone_angle = 30.0f;       // spot: half angle in degrees
  float angular_diameter = 0.0f;  // directional: degrees; > 0 gives soft sun shadows
};

struct CameraKey {
  glm::vec3 position{0.0f}, look_at{0.0f};
};

// A camera's vertical field of view, degrees: camera.fov and --fov.
constexpr double kMinFov = 1.0, kMaxFov = 179.0;

struct CameraSpec {
  std::optional<glm::vec3> position, look_at;  // nullopt: auto (fit to the scene bounds)
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov = 60.0f;            // vertical, degrees
  bool jitter = true;           // sub-pixel Halton jitter per frame, as TAA does
  float orbit = 0.0f;           // degrees swept about the up axis through look_at over all frames
  std::vector<CameraKey> keys;  // if set, the camera moves through these over the frames
  std::optional<uint32_t> file_camera;  // --camera-index: the scene file's camera N, whole
  bool fov_chosen = false;              // --fov: fov stays when a file camera is adopted
};

enum class Placement { Regular, Importance };

// Irregular camera samples placed by an importance map (Harada & Fujita 2014).
struct SampleSpec {
  Placement placement = Placement::Regular;
  bool edges = true;            // importance from depth/normal/material edges of the last frame
  bool cost = true;             // importance from the rays each pixel cost in the last frame
  float uniform_share = 0.25f;  // share of the samples spread uniformly
  uint64_t count = 0;           // camera samples per frame; 0: width * height
};

// How densely one pass shoots: on a grid of resolution_scale x the image (one camera sample per
// cell; 1 = every camera sample), rays_per_pixel rays per chosen sample.
struct PassRate {
  bool enabled = true;
  float resolution_scale = 1.0f;
  uint32_t rays_per_pixel = 1;
};

struct ReflectionSpec : PassRate {
  float max_roughness = 0.5f;  // surfaces rougher than this get no reflection ray
  uint32_t max_rerolls = 8;    // new samples tried when a direction falls below the horizon
};

struct GiSpec {
  bool enabled = true;
  uint64_t budget = 250000;       // diffuse GI rays per frame
  uint32_t rays_per_surfel = 64;  // wanted per surfel per frame before the budget cap
  float new_surfel_boost = 4.0f;  // weight of surfels younger than new_surfel_frames
  uint32_t new_surfel_frames = 4;
  uint32_t tile = 16;                  // spawn tile size, pixels
  uint32_t coverage_stride = 4;        // coverage evaluated on every Nth pixel of a tile
  float coverage_threshold = 1.0f;     // tiles at or above this coverage spawn nothing
  std::optional<float> surfel_radius;  // nullopt: auto (see spawn_surfels)
  uint32_t max_surfels = 262144;
  bool light_connections = true;  // one shadow ray from each GI hit to a light
};

struct AoSpec : PassRate {
  std::optional<float> radius;  // nullopt: auto (2% of the scene diagonal)
};

struct RefractionSpec : PassRate {
  uint32_t max_depth = 2;  // interfaces crossed: 2 = into and out of a glass object
};

struct PassSpecs {
  PassRate shadow;
  ReflectionSpec reflection;
  bool reflected_shadow = true;
  GiSpec gi;
  AoSpec ao;
  RefractionSpec refraction;
  PassRate translucency;
  // Per RayType: its rays run the any-hit alpha test on alpha-tested triangles; false sets
  // their RAY_FLAG_FORCE_OPAQUE (traces/ray.h).
  std::array<bool, kRayTypeCount> alpha_test = {true, true, true, true, true, true, true, true};
};

struct WorkloadSpec {
  std::string file;  // where it was read from ("" if built in code)
  std::string name;
  std::string preset = "pica-pica";
  std::string scene;  // a built-in name or a path (resolved against the spec's folder)
  uint64_t seed = 1;
  uint32_t frames = 1;
  // Frames the renderer runs before frame 0, at frame 0's camera, writing no rays: surfels
  // spawn and the importance map fills in, as in a renderer that has been running a while.
  uint32_t warmup_frames = 0;
  uint32_t width = 1920, height = 1080;
  CameraSpec camera;
  SampleSpec samples;
  std::vector<MaterialRule> materials;
  std::vector<InstanceRule> instances;
  std::array<uint8_t, kRayTypeCount> ray_masks = all_ray_masks();  // inclusion mask per RayType
  std::vector<LightSpec> lights;
  bool lights_from_emission = true;  // emissive objects become spherical lights
  glm::vec3 sky{0.0f};               // radiance of rays that miss (0: no sky)
  PassSpecs passes;
};

enum class ViewProblem { None, NoDirection, NoUp };
// Whether an image can be built looking from position to look_at with up: the two points apart
// and up not along the view (else every ray would be NaN or miss). Up itself must not be zero.
ViewProblem view_problem(const glm::vec3& position, const glm::vec3& look_at, const glm::vec3& up);

struct KeyDoc {
  std::string key, type, default_value, unit, description;
};

// Reads a spec file; bad input (syntax, unknown key, wrong type, out of range) throws
// InputError naming the file, line and key.
WorkloadSpec read_spec(const std::string& path);
// Parses spec text; file names it in errors and anchors relative scene paths.
WorkloadSpec parse_spec(const std::string& text, const std::string& file);
// The spec a built-in scene name gets when no file is given: defaults and that scene.
WorkloadSpec default_spec_for_scene(const std::string& scene);
// Every key: name (dotted; [] marks arrays of tables), type, default, unit, description.
std::vector<KeyDoc> spec_key_docs();

// Presets of pass budgets: "pica-pica" (the talk's budgets) and "full-rate" (every pass at full
// resolution). Throws std::invalid_argument for an unknown name.
PassSpecs preset_passes(const std::string& name);
std::vector<std::string> preset_names();

// "WxH" -> (W, H); false unless both are positive integers.
bool parse_resolution(const std::string& text, uint32_t& width, uint32_t& height);

}  // namespace rtsim::pipeline
