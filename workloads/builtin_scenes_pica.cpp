// A small room in the spirit of SEED's Pica Pica world (Barré-Brisebois et al., "Hybrid
// Rendering for Real-Time Ray Tracing", 2018): a light-blue floor, three pastel walls open to
// the front and the sky, shipping-container boxes, and one sphere per material family of the
// talk (glossy, rough, mirror, glass, translucent, two-layer clear coat), a house plant whose
// leaves are alpha-tested, lit by an emissive sphere named "light". Metres, y up, 4328
// triangles; a camera at (0, 2, 9) sees it all.
//
// Built as SEED's world is, from instances: 8 unique meshes (floor, wall, sphere, light bulb,
// three boxes and the plant) placed 17 times, each placement with its own material. The scene
// also keeps the flattened copy (4328 triangles are cheap), so the passes trace one world-space
// mesh and bvh.instancing = "auto" walks the instances on two levels. Meshes whose instances turn
// by an angle that is not a quarter turn are made at their size, so that each instance's
// transform is a rotation and an offset (its fingerprint is pinned by the tests).
#include "workloads/builtin_scenes.h"

namespace rtsim::builtin {
namespace {

using V = glm::vec3;

constexpr int kSphereLevel = 8;  // 512 triangles per sphere
constexpr float kRoomHalf = 6.0f, kWallHalfHeight = 2.0f;

// The room's unique meshes, in the order of Scene::instanced.meshes.
enum MeshId : uint32_t {
  kFloor,
  kWall,
  kSphere,
  kBulb,
  kContainer,
  kTurnedContainer,
  kCrate,
  kPlant
};

constexpr uint64_t kPlantSeed = 0x91a47ull;
constexpr uint32_t kPlantLeaves = 160;
constexpr uint32_t kLeafTexels = 128;

// A house plant: a stem and a crown of alpha-tested leaf triangles (traces/alpha.h); its leaf
// texture is the scene's only one, at texture offset 0.
UniqueMesh make_plant() {
  UniqueMesh plant;
  plant.add(unit_cube(), V(0.0f, 0.5f, 0.0f), V(0.03f, 0.5f, 0.03f), 0);
  uint32_t mask = plant.add_mask(leaf_mask("pica_leaf", kLeafTexels, 1.0f, 0));
  Pcg32 rng(kPlantSeed);
  add_leaves(plant, kPlantLeaves, 0.3f, V(0.0f, 1.1f, 0.0f), V(0.5f, 0.45f, 0.5f), 0, mask, rng);
  return plant;
}

class PicaBuilder {
 public:
  PicaBuilder() {
    scene_.source = "builtin:pica";
    add_mesh(grid_quad(16), V(1.0f));
    add_mesh(grid_quad(8), V(1.0f));
    add_mesh(octa_sphere(kSphereLevel), V(1.0f));
    add_mesh(octa_sphere(4), V(1.0f));
    add_mesh(unit_cube(), V(1.5f, 0.75f, 0.7f));
    add_mesh(unit_cube(), V(0.7f, 0.75f, 1.5f));
    add_mesh(unit_cube(), V(0.4f));
    add_unique(make_plant());
  }

  uint32_t material(const Material& m) {
    scene_.materials.push_back(m);
    return uint32_t(scene_.materials.size() - 1);
  }

  // Places mesh at p -> offset + rotation * (scale * p), an object of its own.
  void place(MeshId mesh, uint32_t material, const char* object, V offset, V scale,
             const glm::mat3& rotation = glm::mat3(1.0f)) {
    scene_.object_names.push_back(object);
    scene_.instanced.instances.push_back({mesh, placement(rotation, scale, offset)});
    scene_.instance_material_ids.push_back(material);
    scene_.instance_object_ids.push_back(uint32_t(scene_.object_names.size() - 1));
  }

  // The scene with its flattened copy made from the instances. Every instance names its
  // material, so the meshes' own material ids (0) are never read.
  Scene finish() {
    flat_mesh(scene_);
    return std::move(scene_);
  }

 private:
  void add_mesh(const MeshTemplate& t, V size) {
    UniqueMesh m;
    m.add(t, V(0.0f), size, 0);
    add_unique(std::move(m));
  }

  void add_unique(UniqueMesh m) {
    scene_.instanced.meshes.push_back(std::move(m.mesh));
    scene_.mesh_material_ids.push_back(std::move(m.materials));
  }

  Scene scene_;
};

void add_room(PicaBuilder& b) {
  uint32_t floor = b.material(make_material("floor", V(0.55f, 0.75f, 0.9f), 0.8f));
  uint32_t wall = b.material(make_material("wall", V(0.93f, 0.87f, 0.76f), 0.9f));
  uint32_t accent = b.material(make_material("wall_accent", V(0.98f, 0.72f, 0.6f), 0.9f));
  b.place(kFloor, floor, "floor", V(0.0f), V(kRoomHalf, 1.0f, kRoomHalf));
  // Grid quads face +y; the matrices (columns: images of x, y, z) turn them into walls facing
  // into the room without mirroring, so the winding stays outward.
  const V wall_scale(kRoomHalf, 1.0f, kWallHalfHeight);
  b.place(kWall, wall, "wall_back", V(0.0f, kWallHalfHeight, -kRoomHalf), wall_scale,
          glm::mat3(V(1, 0, 0), V(0, 0, 1), V(0, -1, 0)));
  b.place(kWall, accent, "wall_left", V(-kRoomHalf, kWallHalfHeight, 0.0f), wall_scale,
          glm::mat3(V(0, 0, -1), V(1, 0, 0), V(0, -1, 0)));
  b.place(kWall, accent, "wall_right", V(kRoomHalf, kWallHalfHeight, 0.0f), wall_scale,
          glm::mat3(V(0, 0, 1), V(-1, 0, 0), V(0, -1, 0)));
}

void add_spheres(PicaBuilder& b) {
  auto put = [&](const Material& m, const char* object, V center, float radius) {
    b.place(kSphere, b.material(m), object, center, V(radius));
  };
  put(make_material("glossy_yellow", V(0.95f, 0.8f, 0.2f), 0.3f), "glossy_sphere",
      V(-3.5f, 0.8f, -1.5f), 0.8f);
  put(make_material("rough_pink", V(0.95f, 0.55f, 0.7f), 0.9f), "rough_sphere",
      V(-1.5f, 0.7f, 1.0f), 0.7f);
  Material mirror = make_material("mirror", V(0.95f), 0.0f);
  mirror.metalness = 1.0f;
  put(mirror, "mirror_sphere", V(0.5f, 1.0f, -2.5f), 1.0f);
  Material glass = make_material("glass", V(1.0f), 0.0f);
  glass.transmission = 1.0f;
  glass.ior = 1.5f;
  put(glass, "glass_sphere", V(1.5f, 0.7f, 1.2f), 0.7f);
  Material translucent = make_material("translucent_mint", V(0.5f, 0.9f, 0.7f), 0.6f);
  translucent.translucency = 0.8f;
  put(translucent, "translucent_sphere", V(3.5f, 0.6f, -0.5f), 0.6f);
  Material layered = make_material("clear_coat_red", V(0.9f, 0.25f, 0.2f), 0.5f);
  layered.layers = 2;
  put(layered, "layered_sphere", V(-0.5f, 0.5f, 3.0f), 0.5f);
}

void add_boxes(PicaBuilder& b) {
  // Rotations by Pythagorean angles (3-4-5, 7-24-25) need no trigonometry. The blue container
  // sits 1 cm above the red one so no faces are coplanar.
  b.place(kContainer, b.material(make_material("container_red", V(0.75f, 0.2f, 0.15f), 0.7f)),
          "container_red", V(-4.0f, 0.75f, -4.2f), V(1.0f));
  b.place(kContainer, b.material(make_material("container_blue", V(0.2f, 0.35f, 0.7f), 0.7f)),
          "container_blue", V(-4.0f, 2.26f, -4.2f), V(1.0f), rotation_y(0.96f, 0.28f));
  b.place(kTurnedContainer,
          b.material(make_material("container_brown", V(0.5f, 0.33f, 0.2f), 0.8f)),
          "container_brown", V(4.2f, 0.75f, -4.0f), V(1.0f), rotation_y(0.8f, 0.6f));
  b.place(kCrate, b.material(make_material("glossy_white", V(0.9f), 0.2f)), "glossy_box",
          V(2.5f, 0.4f, -2.0f), V(1.0f), rotation_y(0.6f, 0.8f));
}

void add_house_plant(PicaBuilder& b) {
  const V at(-4.6f, 0.0f, 1.8f);
  b.place(kCrate, b.material(make_material("terracotta", V(0.7f, 0.35f, 0.2f), 0.8f)), "pot",
          at + V(0.0f, 0.3f, 0.0f), V(0.75f));
  Material leaf = make_material("leaf", V(0.25f, 0.55f, 0.15f), 0.6f);
  leaf.translucency = 0.5f;
  b.place(kPlant, b.material(leaf), "house_plant", at + V(0.0f, 0.5f, 0.0f), V(1.0f));
}

}  // namespace

Scene make_pica() {
  PicaBuilder b;
  add_room(b);
  add_spheres(b);
  add_boxes(b);
  add_house_plant(b);
  Material light = make_material("light", V(1.0f), 1.0f);
  light.emission = V(12.0f, 11.0f, 9.5f);
  b.place(kBulb, b.material(light), "light", V(0.0f, 3.6f, 0.5f), V(0.4f));
  return b.finish();
}

}  // namespace rtsim::builtin
