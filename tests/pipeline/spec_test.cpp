// Workload specs: every key read with its default, unknown keys and bad values rejected with
// the file, line and key, presets, overrides, and the documentation list.
#include "workloads/pipeline/spec.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

#include "traces/error.h"
#include "workloads/pipeline/workload.h"

namespace rtsim::pipeline {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_spec(text, "w.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Spec, DefaultsFollowThePicaPicaPreset) {
  WorkloadSpec s = parse_spec("scene = \"cornell\"\n", "dir/w.toml");
  EXPECT_EQ(s.name, "w");
  EXPECT_EQ(s.scene, "cornell");  // built-ins are not paths
  EXPECT_EQ(s.width, 1920u);
  EXPECT_EQ(s.height, 1080u);
  EXPECT_EQ(s.frames, 1u);
  EXPECT_FLOAT_EQ(s.passes.shadow.resolution_scale, 1.0f);
  EXPECT_FLOAT_EQ(s.passes.reflection.resolution_scale, 0.5f);
  EXPECT_TRUE(s.passes.reflected_shadow);
  EXPECT_EQ(s.passes.gi.budget, 250000u);
  EXPECT_FLOAT_EQ(s.passes.ao.resolution_scale, 0.5f);
  EXPECT_FALSE(s.camera.position.has_value());  // auto
  EXPECT_TRUE(s.lights_from_emission);
}

TEST(Spec, ReadsEveryKindOfKey) {
  WorkloadSpec s = parse_spec(R"(
name = "x"
preset = "full-rate"
scene = "../scenes/a.obj"
seed = 9
frames = 3
resolution = "64x32"
sky = [0.1, 0.2, 0.3]
[camera]
position = [1, 2, 3]
look_at = "auto"
fov = 45
orbit = 90
[[camera.key]]
position = [0, 0, 1]
look_at = [0, 0, 0]
[[camera.key]]
position = [0, 0, 2]
look_at = [0, 0, 0]
[samples]
placement = "importance"
uniform_share = 0.5
[[material]]
match = "floor*"
roughness = 0.1
layers = 2
emission = [1, 1, 1]
[[light]]
type = "sphere"
position = [0, 5, 0]
radius = 0.5
intensity = 20
[[light]]
type = "directional"
direction = [0, -1, 0]
angular_diameter = 0.5
[shadow]
rays_per_pixel = 2
[reflection]
max_roughness = 0.3
[gi]
budget = 1000
surfel_radius = 0.25
[ao]
radius = 0.5
[refraction]
enabled = false
)",
                              "/specs/w.toml");
  EXPECT_EQ(s.name, "x");
  EXPECT_EQ(s.scene, "/scenes/a.obj");  // relative to the spec's folder
  EXPECT_EQ(s.seed, 9u);
  EXPECT_EQ(s.frames, 3u);
  EXPECT_EQ(s.width, 64u);
  EXPECT_EQ(s.height, 32u);
  EXPECT_FLOAT_EQ(s.sky.z, 0.3f);
  EXPECT_EQ(*s.camera.position, glm::vec3(1, 2, 3));
  EXPECT_FALSE(s.camera.look_at.has_value());
  EXPECT_FLOAT_EQ(s.camera.fov, 45.0f);
  ASSERT_EQ(s.camera.keys.size(), 2u);
  EXPECT_FLOAT_EQ(s.camera.keys[1].position.z, 2.0f);
  EXPECT_EQ(s.samples.placement, Placement::Importance);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].match, "floor*");
  EXPECT_FLOAT_EQ(*s.materials[0].roughness, 0.1f);
  EXPECT_EQ(*s.materials[0].layers, 2);
  EXPECT_FALSE(s.materials[0].metalness.has_value());
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].type, LightType::Sphere);
  EXPECT_FLOAT_EQ(*s.lights[0].radius, 0.5f);
  EXPECT_EQ(s.lights[1].type, LightType::Directional);
  EXPECT_EQ(s.passes.shadow.rays_per_pixel, 2u);
  EXPECT_FLOAT_EQ(s.passes.reflection.max_roughness, 0.3f);
  EXPECT_FLOAT_EQ(s.passes.reflection.resolution_scale, 1.0f);  // full-rate preset
  EXPECT_EQ(s.passes.gi.budget, 1000u);
  EXPECT_FLOAT_EQ(*s.passes.gi.surfel_radius, 0.25f);
  EXPECT_FLOAT_EQ(*s.passes.ao.radius, 0.5f);
  EXPECT_FALSE(s.passes.refraction.enabled);
}

TEST(Spec, UnknownKeyNamesKeyAndLine) {
  EXPECT_EQ(error_of("scene = \"cornell\"\n[camera]\nfov = 40\nfvo = 50\n"),
            "w.toml: line 4: unknown key 'camera.fvo'");
  EXPECT_EQ(error_of("scene = \"cornell\"\nshadows = 1\n"),
            "w.toml: line 2: unknown key 'shadows'");
  EXPECT_EQ(error_of("scene = \"cornell\"\n[[light]]\ntype = \"point\"\ncolour = [1, 1, 1]\n"),
            "w.toml: line 4: unknown key 'light[].colour'");
}

TEST(Spec, BadValuesNameKeyAndLine) {
  EXPECT_EQ(error_of("scene = \"cornell\"\nframes = 0\n"),
            "w.toml: line 2: key 'frames': must be in [1, 100000]");
  EXPECT_EQ(error_of("scene = \"cornell\"\nresolution = \"1920*1080\"\n"),
            "w.toml: line 2: key 'resolution': expected WxH with positive integers, e.g. "
            "\"1920x1080\"");
  EXPECT_EQ(error_of("scene = \"cornell\"\n[camera]\nfov = \"wide\"\n"),
            "w.toml: line 3: key 'camera.fov': expected a finite number");
  EXPECT_EQ(error_of("scene = \"cornell\"\n[[light]]\ntype = \"area\"\n"),
            "w.toml: line 3: key 'light[].type': expected one of \"point\", \"spot\", "
            "\"directional\", \"sphere\", got \"area\"");
  EXPECT_EQ(error_of("scene = \"cornell\"\npreset = \"fast\"\n"),
            "w.toml: line 2: key 'preset': expected one of \"pica-pica\", \"full-rate\", got "
            "\"fast\"");
  EXPECT_EQ(error_of("scene = \"cornell\"\n[[material]]\nroughness = 0.5\n"),
            "w.toml: line 2: key 'material[].match': a material rule needs a non-empty match "
            "pattern");
  EXPECT_EQ(error_of("frames = 2\n"), "w.toml: key 'scene': missing: a spec needs a scene");
  EXPECT_EQ(error_of("scene = \"cornell\"\nsky = [1, 2]\n"),
            "w.toml: line 2: key 'sky': expected an array of 3 numbers");
  EXPECT_NE(error_of("scene = \"cornell\"\n[camera\n").find("w.toml: line 2:"), std::string::npos);
}

TEST(Spec, InstanceRulesAndRayMasks) {
  WorkloadSpec s = parse_spec(
      "scene = \"city:1000\"\nframes = 3\n[[instances]]\nmatch = \"cars\"\naxis = [0, 2, 0]\n"
      "[[instances.key]]\n[[instances.key]]\ntranslate = [4, 0, 0]\nrotate = 30\nscale = 2\n"
      "[[instances]]\nmatch = \"tree*\"\nmask = 2\n[ray_masks]\nshadow = 1\n",
      "w.toml");
  ASSERT_EQ(s.instances.size(), 2u);
  EXPECT_EQ(s.instances[0].match, "cars");
  EXPECT_FALSE(s.instances[0].mask);
  EXPECT_EQ(s.instances[0].motion.axis, glm::vec3(0, 1, 0)) << "normalized";
  ASSERT_EQ(s.instances[0].motion.keys.size(), 2u);
  EXPECT_EQ(s.instances[0].motion.keys[1].translate, glm::vec3(4, 0, 0));
  EXPECT_EQ(s.instances[0].motion.keys[1].rotate, 30.0f);
  EXPECT_EQ(s.instances[0].motion.keys[1].scale, 2.0f);
  EXPECT_EQ(s.instances[1].mask, uint8_t(2));
  EXPECT_EQ(s.instances[1].where, "line 11");
  EXPECT_EQ(s.ray_masks[size_t(RayType::Shadow)], 1u);
  EXPECT_EQ(s.ray_masks[size_t(RayType::AO)], 255u);
  EXPECT_EQ(error_of("scene = \"city:1000\"\n[[instances]]\nmatch = \"cars\"\n"),
            "w.toml: line 2: key 'instances[]': an instance rule needs a mask or motion keys "
            "([[instances.key]])");
  EXPECT_EQ(error_of("scene = \"city:1000\"\n[[instances]]\nmatch = \"cars\"\nmask = 256\n"),
            "w.toml: line 4: key 'instances[].mask': must be in [1, 255]");
  EXPECT_EQ(error_of("scene = \"city:1000\"\n[ray_masks]\nao = 0\n"),
            "w.toml: line 3: key 'ray_masks.ao': must be in [1, 255]");
  EXPECT_EQ(error_of("scene = \"city:1000\"\n[[instances]]\nmatch = \"cars\"\naxis = [0, 0, 0]\n"
                     "[[instances.key]]\n"),
            "w.toml: line 4: key 'instances[].axis': must not be zero or shorter than 1e-15");
}

TEST(Spec, AlphaTestPerRayType) {
  WorkloadSpec s = parse_spec("scene = \"pica\"\n[alpha_test]\ndiffuse_gi = false\n", "w.toml");
  for (int t = 0; t < kRayTypeCount; ++t)
    EXPECT_EQ(s.passes.alpha_test[size_t(t)], RayType(t) != RayType::DiffuseGI)
        << ray_type_name(RayType(t));
  EXPECT_EQ(error_of("scene = \"pica\"\n[alpha_test]\nao = 1\n"),
            "w.toml: line 3: key 'alpha_test.ao': expected true or false");
}

TEST(Spec, ADegenerateCameraNamesItsKey) {
  const std::string scene = "scene = \"cornell\"\n[camera]\n";
  EXPECT_EQ(error_of(scene + "position = [1, 2, 3]\nlook_at = [1, 2, 3]\n"),
            "w.toml: line 4: key 'camera.look_at': equals position: the camera has no view "
            "direction");
  EXPECT_EQ(error_of(scene + "position = [0, 0, 0]\nlook_at = [0, 5, 0]\n"),
            "w.toml: line 2: key 'camera.up': is parallel to the view direction (position to "
            "look_at): the image has no up; choose another up");
  EXPECT_EQ(error_of(scene + "up = [0, 0, 0]\n"),
            "w.toml: line 3: key 'camera.up': must not be zero or shorter than 1e-15");
  EXPECT_NE(error_of(scene + "[[camera.key]]\nposition = [0, 0, 0]\nlook_at = [0, 0, 0]\n")
                .find("key 'camera.key[].look_at': equals position"),
            std::string::npos);
  EXPECT_EQ(error_of(scene + "position = [0, 0, 0]\nlook_at = [0, 0, -5]\n"), "") << "a view";
}

// Issue 63: cameras, look-at points and lights share the scene's range (+-1e15), and directions
// must normalize; each names its key.
TEST(Spec, PointsBeyondTheTracedRangeNameTheirKey) {
  const std::string scene = "scene = \"cornell\"\n";
  EXPECT_EQ(error_of(scene + "[camera]\nposition = [2e18, 0, 0]\n"),
            "w.toml: line 3: key 'camera.position': (2e+18, 0, 0) is beyond +-1e+15, the range "
            "rtsim traces (Embree's rays reach +-1.8e18; cameras and ray offsets around the "
            "scene must stay inside)");
  EXPECT_NE(error_of(scene + "[camera]\nlook_at = [0, -1.1e15, 0]\n")
                .find("line 3: key 'camera.look_at': (0, -1100000000000000, 0) is beyond"),
            std::string::npos);
  EXPECT_NE(error_of(scene + "[[camera.key]]\nposition = [0, 0, 5]\nlook_at = [0, 0, -1.9e18]\n")
                .find("line 4: key 'camera.key[].look_at': (0, 0, -1.9e+18) is beyond"),
            std::string::npos);
  EXPECT_NE(error_of(scene + "[[light]]\nposition = [0, 5e17, 0]\n")
                .find("line 3: key 'light[].position': (0, 5e+17, 0) is beyond"),
            std::string::npos);
  EXPECT_EQ(error_of(scene + "[camera]\nup = [1e30, 1, 0]\n"),
            "w.toml: line 3: key 'camera.up': (1e+30, 1, 0) has a component beyond +-1e+15; "
            "give a shorter vector");
  EXPECT_EQ(error_of(scene + "[[light]]\ndirection = [1e-30, 0, 0]\n"),
            "w.toml: line 3: key 'light[].direction': must not be zero or shorter than 1e-15");
  EXPECT_EQ(error_of(scene + "[[light]]\ndirection = [0, -1e300, 0]\n"),
            "w.toml: line 3: key 'light[].direction': expected an array of 3 finite numbers "
            "(within a float's range)");
  EXPECT_EQ(error_of(scene + "[camera]\nposition = [1e15, -1e15, 0]\nlook_at = [0, 0, 0]\n"), "")
      << "the range's edge";
}

TEST(Spec, OptionPointsBeyondTheTracedRangeNameTheOption) {
  auto message = [](OverrideText t) {
    try {
      make_overrides(t);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  OverrideText camera;
  camera.camera = "2e18,0,0";
  EXPECT_EQ(message(camera).rfind("--camera 2e18,0,0: (2e+18, 0, 0) is beyond +-1e+15", 0), 0u)
      << message(camera);
  OverrideText look_at;
  look_at.look_at = "0,-3e18,0";
  EXPECT_EQ(message(look_at).rfind("--look-at 0,-3e18,0: (0, -3e+18, 0) is beyond", 0), 0u);
  OverrideText up;
  up.up = "1e30,1,0";
  EXPECT_EQ(message(up),
            "--up 1e30,1,0: (1e+30, 1, 0) has a component beyond +-1e+15; give a "
            "shorter vector");
  up.up = "1e-30,0,0";
  EXPECT_EQ(message(up), "--up 1e-30,0,0: must not be zero or shorter than 1e-15");
}

TEST(Spec, ResolutionSyntax) {
  uint32_t w = 0, h = 0;
  EXPECT_TRUE(parse_resolution("1920x1080", w, h));
  EXPECT_EQ(w, 1920u);
  EXPECT_EQ(h, 1080u);
  EXPECT_FALSE(parse_resolution("0x10", w, h));
  EXPECT_FALSE(parse_resolution("10x", w, h));
  EXPECT_FALSE(parse_resolution("x10", w, h));
  EXPECT_FALSE(parse_resolution("10x10x10", w, h));
  EXPECT_FALSE(parse_resolution("-5x10", w, h));
}

TEST(Spec, OverridesReplaceSpecValues) {
  WorkloadSpec s =
      parse_spec("scene = \"cornell\"\nseed = 3\n[camera]\nposition = [1, 2, 3]\n", "w.toml");
  apply_overrides(s, make_overrides({"320x200", 4, 77, "pica"}));
  EXPECT_FALSE(s.camera.position.has_value());  // a new scene gets an automatic camera
  EXPECT_EQ(s.width, 320u);
  EXPECT_EQ(s.height, 200u);
  EXPECT_EQ(s.frames, 4u);
  EXPECT_EQ(s.seed, 77u);
  EXPECT_EQ(s.scene, "pica");
  EXPECT_THROW(make_overrides({"320"}), InputError);
}

TEST(Spec, FovAndCameraIndexOverridesAreCheckedWhereTheyAreRead) {
  auto message = [](const OverrideText& t) {
    try {
      make_overrides(t);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  OverrideText wide;
  wide.fov = 180.0;
  EXPECT_EQ(message(wide), "--fov 180: expected a vertical field of view from 1 to 179 degrees");
  wide.fov = 179.0;
  EXPECT_EQ(message(wide), "accepted");
  OverrideText both;
  both.camera_index = 1;
  both.look_at = "0,0,0";
  EXPECT_EQ(message(both).rfind("--camera-index: cannot be combined with --camera or --look-at", 0),
            0u)
      << message(both);
  WorkloadSpec s = parse_spec(
      "scene = \"cornell\"\n[camera]\nposition = [1, 2, 3]\nfov = 50\n[[camera.key]]\n"
      "position = [0, 0, 1]\nlook_at = [0, 0, 0]\n",
      "w.toml");
  OverrideText index;
  index.camera_index = 1;
  apply_overrides(s, make_overrides(index));
  EXPECT_FALSE(s.camera.position.has_value()) << "the file's camera replaces the spec's";
  EXPECT_TRUE(s.camera.keys.empty());
  EXPECT_EQ(s.camera.file_camera, 1u);
  EXPECT_FALSE(s.camera.fov_chosen) << "the file camera's angle unless --fov";
}

TEST(Spec, CameraOverridesReplaceTheSpecsViewAndRefuseADegenerateOne) {
  WorkloadSpec s = parse_spec(
      "scene = \"cornell\"\n[camera]\nposition = [1, 2, 3]\nlook_at = [0, 0, 0]\n", "w.toml");
  OverrideText text;
  text.camera = "0,1,5";
  text.up = "0,0,1";
  apply_overrides(s, make_overrides(text));
  EXPECT_EQ(*s.camera.position, glm::vec3(0, 1, 5));
  EXPECT_EQ(*s.camera.look_at, glm::vec3(0, 0, 0)) << "the spec's look-at point stays";
  EXPECT_EQ(s.camera.up, glm::vec3(0, 0, 1));
  auto message = [&](OverrideText t) {
    WorkloadSpec spec = s;
    try {
      apply_overrides(spec, make_overrides(t));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  OverrideText same;
  same.camera = "0,0,0";
  EXPECT_NE(message(same).find("--camera: the camera position equals the look-at point"),
            std::string::npos)
      << message(same);
  OverrideText parallel;
  parallel.up = "0,1,5";
  EXPECT_NE(message(parallel).find("--up: parallel to the view direction"), std::string::npos);
  OverrideText zero;
  zero.up = "0,0,0";
  EXPECT_NE(message(zero).find("--up 0,0,0: must not be zero"), std::string::npos);
  OverrideText malformed;
  malformed.look_at = "1,2";
  EXPECT_EQ(message(malformed), "--look-at 1,2: expected three numbers X,Y,Z, e.g. 0,1.5,4");
}

TEST(Spec, EveryKeyIsDocumentedOnceWithDescription) {
  std::vector<KeyDoc> docs = spec_key_docs();
  EXPECT_GT(docs.size(), 60u);
  std::set<std::string> seen;
  for (const KeyDoc& d : docs) {
    EXPECT_TRUE(seen.insert(d.key).second) << d.key;
    EXPECT_FALSE(d.description.empty()) << d.key;
    EXPECT_FALSE(d.type.empty()) << d.key;
  }
  for (const char* key : {"camera.fov", "light[].radius", "material[].ior", "gi.budget",
                          "reflection.max_rerolls", "samples.placement", "ao.radius"})
    EXPECT_TRUE(seen.count(key)) << key;
}

// workloads/README.md lists every key, so the documentation cannot fall behind the code.
TEST(Spec, ReadmeListsEveryKey) {
  std::ifstream in(std::string(RTSIM_SOURCE_DIR) + "/workloads/README.md");
  ASSERT_TRUE(in) << "workloads/README.md is missing";
  std::stringstream text;
  text << in.rdbuf();
  for (const KeyDoc& d : spec_key_docs())
    EXPECT_NE(text.str().find("`" + d.key + "`"), std::string::npos)
        << d.key << " is not in workloads/README.md";
}

TEST(Spec, EverySampleSpecParses) {
  for (const char* name : {"cornell", "pica", "grid", "foliage", "sponza", "sibenik", "conference",
                           "bunny", "dragon", "cornell-box", "pica-orbit", "city-traffic"}) {
    std::string path = std::string(RTSIM_SOURCE_DIR) + "/workloads/specs/" + name + ".toml";
    WorkloadSpec s = read_spec(path);
    EXPECT_EQ(s.name, name);
  }
}

}  // namespace
}  // namespace rtsim::pipeline
