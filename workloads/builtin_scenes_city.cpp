// "city:N": a city built as games build worlds, from instances. Unique meshes: six buildings
// (towers and blocks of one to three tiers whose facades are bays of inset windows, glazed with
// glossy glass), four street props (a lamp, a car, a bench, a tree) and a street tile (asphalt, a
// raised sidewalk, dashed centre lines). Blocks of four lots fill a street grid in square shells
// from the origin; each lot gets a building turned by a multiple of 90 degrees about +y
// (matrices of 0 and +-1), scaled and jittered, and props line the kerbs and parking lanes. N is
// the instanced triangles asked for: whole blocks are added until N is reached. Like forest:N,
// the scene keeps only its unique geometry and instances, and it brings a camera over a street
// corner. Metres, y up; seeded, bit-identical on every machine (+, *, / and sqrt only).
#include <cmath>

#include "workloads/builtin_scenes.h"

namespace rtsim::builtin {
namespace {

using V = glm::vec3;

constexpr uint64_t kCitySeed = 0xc17ull;
constexpr float kFloorHeight = 3.5f;
constexpr float kWindowInset = 0.3f;
constexpr float kSlabHalf = 0.25f;     // half the thickness of a roof slab
constexpr float kCornice = 0.4f;       // how far a roof slab overhangs its facades
constexpr float kBlockPitch = 64.0f;   // a 48 m block and a 16 m street
constexpr float kBlockHalf = 24.0f;    // block centre to kerb
constexpr float kKerbHeight = 0.15f;   // the sidewalk's top; the street is at y = 0
constexpr float kLotOffset = 10.0f;    // four 20 m lots, centred at (+-10, +-10)
constexpr float kParkingLane = 25.5f;  // block centre to a parked car's centre
constexpr int kStreetCells = 16;       // grid_quad: 512 triangles

enum Object : uint32_t { kBuildings, kLamps, kCars, kBenches, kTrees, kGround };
enum MaterialId : uint32_t {
  kConcrete,
  kBrick,
  kGlass,
  kAsphalt,
  kPavement,
  kPaint,
  kCarPaint,
  kSteel,
  kWood,
  kFoliage
};

// A prism of floors on a footprint of half sizes (half_x, half_z), each facade split into bays
// of one window per floor.
struct Tier {
  float half_x, half_z;
  int floors, bays_x, bays_z;
};

struct BuildingVariant {
  std::vector<Tier> tiers;  // bottom to top
  MaterialId facade;
};

// Every footprint fits a 20 m lot with room for the scale and jitter of add_building.
const std::vector<BuildingVariant>& building_variants() {
  static const std::vector<BuildingVariant> variants = {
      {{{9, 9, 3, 4, 4}, {7, 7, 22, 3, 3}}, kConcrete},               // tower on a podium
      {{{6, 6, 30, 2, 2}}, kConcrete},                                // slender tower
      {{{9, 9, 10, 5, 5}}, kConcrete},                                // office block
      {{{9, 5, 7, 5, 3}}, kBrick},                                    // slab
      {{{9, 9, 4, 4, 4}, {7, 7, 6, 3, 3}, {5, 5, 6, 2, 2}}, kBrick},  // stepped tower
      {{{9, 7, 3, 5, 4}}, kBrick},                                    // shop row
  };
  return variants;
}

// The unique meshes in order: the props, the street tile, then a building per variant.
enum MeshId : uint32_t { kLamp, kCar, kBench, kTree, kStreetTile, kFirstBuilding };

// Rotation about +y by k quarter turns: exact, its entries 0 and +-1.
glm::mat3 quarter_turn(uint32_t k) {
  const float c[4] = {1, 0, -1, 0}, s[4] = {0, 1, 0, -1};
  return rotation_y(c[k % 4], s[k % 4]);
}

// Appends the quad corner, corner + u, corner + u + v, corner + v, facing u x v.
void add_quad(MeshTemplate& t, const V& corner, const V& u, const V& v) {
  auto base = uint32_t(t.positions.size());
  t.positions.insert(t.positions.end(), {corner, corner + u, corner + u + v, corner + v});
  t.triangles.push_back({base, base + 1, base + 2});
  t.triangles.push_back({base, base + 2, base + 3});
}

// One floor of a facade bay facing +z at z = 0, x in [-width/2, width/2], y in [0, floor
// height]: the wall around a window and the window's reveals (16 triangles), and the glass set
// back in the wall (2 triangles).
struct Bay {
  MeshTemplate wall, glass;
};

Bay window_bay(float width) {
  const float half = 0.5f * width, a = 0.35f * width, sill = 0.9f, head = 3.0f;
  const float h = kFloorHeight, d = kWindowInset, side = half - a, tall = head - sill;
  Bay bay;
  add_quad(bay.wall, V(-half, 0, 0), V(side, 0, 0), V(0, h, 0));
  add_quad(bay.wall, V(a, 0, 0), V(side, 0, 0), V(0, h, 0));
  add_quad(bay.wall, V(-a, 0, 0), V(2 * a, 0, 0), V(0, sill, 0));
  add_quad(bay.wall, V(-a, head, 0), V(2 * a, 0, 0), V(0, h - head, 0));
  add_quad(bay.wall, V(-a, sill, -d), V(0, tall, 0), V(0, 0, d));
  add_quad(bay.wall, V(a, sill, -d), V(0, 0, d), V(0, tall, 0));
  add_quad(bay.wall, V(-a, sill, -d), V(0, 0, d), V(2 * a, 0, 0));
  add_quad(bay.wall, V(-a, head, -d), V(2 * a, 0, 0), V(0, 0, d));
  add_quad(bay.glass, V(-a, sill, -d), V(2 * a, 0, 0), V(0, tall, 0));
  return bay;
}

// The tier's four facades from y = base, bay by bay, under a roof slab that overhangs them as
// a cornice; returns the top of the slab.
float add_tier(UniqueMesh& building, const Tier& tier, float base, uint32_t facade) {
  for (uint32_t side = 0; side < 4; ++side) {
    const bool along_x = side % 2 == 0;  // quarter_turn(side) faces +z, +x, -z, -x
    const float half_width = along_x ? tier.half_x : tier.half_z;
    const float depth = along_x ? tier.half_z : tier.half_x;
    const int bays = along_x ? tier.bays_x : tier.bays_z;
    const float width = 2 * half_width / float(bays);
    const Bay bay = window_bay(width);
    const glm::mat3 turn = quarter_turn(side);
    for (int floor = 0; floor < tier.floors; ++floor) {
      for (int i = 0; i < bays; ++i) {
        V at = turn * V(-half_width + (float(i) + 0.5f) * width, base + float(floor) * kFloorHeight,
                        depth);
        building.add(bay.wall, at, V(1.0f), facade, turn);
        building.add(bay.glass, at, V(1.0f), kGlass, turn);
      }
    }
  }
  const float top = base + float(tier.floors) * kFloorHeight;
  building.add(unit_cube(), V(0, top + kSlabHalf, 0),
               V(tier.half_x + kCornice, kSlabHalf, tier.half_z + kCornice), facade);
  return top + 2 * kSlabHalf;
}

UniqueMesh make_building(const BuildingVariant& variant) {
  UniqueMesh building;
  building.object = kBuildings;
  float base = 0;
  for (const Tier& tier : variant.tiers) base = add_tier(building, tier, base, variant.facade);
  const Tier& top = variant.tiers.back();
  building.add(unit_cube(), V(0, base + 1.5f, 0), V(0.4f * top.half_x, 1.5f, 0.4f * top.half_z),
               kConcrete);  // the plant room on the roof
  return building;
}

// A lamp post whose arm reaches over the street at +z.
UniqueMesh make_lamp() {
  UniqueMesh lamp;
  lamp.object = kLamps;
  lamp.add(unit_cube(), V(0, 0.3f, 0), V(0.15f, 0.3f, 0.15f), kSteel);
  lamp.add(unit_cube(), V(0, 3.0f, 0), V(0.08f, 3.0f, 0.08f), kSteel);
  lamp.add(unit_cube(), V(0, 5.95f, 0.6f), V(0.05f, 0.05f, 0.6f), kSteel);
  lamp.add(octa_sphere(3), V(0, 5.8f, 1.2f), V(0.25f, 0.12f, 0.25f), kGlass);
  return lamp;
}

// A car 4.4 m long along x: body, glazed cabin, roof and four wheels.
UniqueMesh make_car() {
  UniqueMesh car;
  car.object = kCars;
  car.add(unit_cube(), V(0, 0.65f, 0), V(2.2f, 0.35f, 0.9f), kCarPaint);
  car.add(unit_cube(), V(-0.2f, 1.25f, 0), V(1.2f, 0.25f, 0.8f), kGlass);
  car.add(unit_cube(), V(-0.2f, 1.53f, 0), V(1.15f, 0.03f, 0.78f), kCarPaint);
  for (float x : {-1.4f, 1.4f})
    for (float z : {-0.85f, 0.85f})
      car.add(octa_sphere(3), V(x, 0.35f, z), V(0.35f, 0.35f, 0.12f), kAsphalt);
  return car;
}

// A bench facing +z: seat, back and two legs.
UniqueMesh make_bench() {
  UniqueMesh bench;
  bench.object = kBenches;
  bench.add(unit_cube(), V(0, 0.45f, 0), V(0.9f, 0.04f, 0.22f), kWood);
  bench.add(unit_cube(), V(0, 0.8f, -0.2f), V(0.9f, 0.2f, 0.03f), kWood);
  for (float x : {-0.8f, 0.8f})
    bench.add(unit_cube(), V(x, 0.22f, 0), V(0.04f, 0.22f, 0.2f), kSteel);
  return bench;
}

UniqueMesh make_tree() {
  UniqueMesh tree;
  tree.object = kTrees;
  tree.add(unit_cube(), V(0, 1.5f, 0), V(0.15f, 1.5f, 0.15f), kWood);
  tree.add(octa_sphere(5), V(0, 4.0f, 0), V(1.6f, 1.5f, 1.6f), kFoliage);
  return tree;
}

// The street tile around a block: asphalt out to the middle of the streets, the raised
// sidewalk, and the dashed centre lines of the streets on its +x and +z edges (each tile owns
// two, so the grid of tiles has one of each).
UniqueMesh make_street_tile() {
  UniqueMesh tile;
  tile.object = kGround;
  const float half = 0.5f * kBlockPitch;
  tile.add(grid_quad(kStreetCells), V(0), V(half, 1.0f, half), kAsphalt);
  tile.add(unit_cube(), V(0, 0.5f * kKerbHeight - 0.025f, 0),
           V(kBlockHalf, 0.5f * kKerbHeight + 0.025f, kBlockHalf), kPavement);
  MeshTemplate dash;  // 3 m by 15 cm along z, just above the asphalt
  add_quad(dash, V(-0.075f, 0.01f, -1.5f), V(0, 0, 3.0f), V(0.15f, 0, 0));
  for (uint32_t edge : {0u, 3u})  // quarter turns 0 and 3 take +x to +x and +z
    for (int i = 0; i < 6; ++i)   // one dash every 8 m between the crossings
      tile.add(dash, quarter_turn(edge) * V(half, 0, float(8 * i - 20)), V(1.0f), kPaint,
               quarter_turn(edge));
  return tile;
}

std::vector<Material> city_materials() {
  Material glass = make_material("window_glass", V(0.35f, 0.45f, 0.5f), 0.05f);
  Material car_paint = make_material("car_paint", V(0.6f, 0.08f, 0.06f), 0.3f);
  car_paint.metalness = 1.0f;
  Material steel = make_material("steel", V(0.55f), 0.4f);
  steel.metalness = 1.0f;
  return {make_material("concrete", V(0.62f, 0.6f, 0.57f), 0.85f),
          make_material("brick", V(0.55f, 0.3f, 0.22f), 0.9f),
          glass,
          make_material("asphalt", V(0.12f, 0.12f, 0.13f), 0.95f),
          make_material("pavement", V(0.65f, 0.63f, 0.6f), 0.9f),
          make_material("road_paint", V(0.9f), 0.8f),
          car_paint,
          steel,
          make_material("wood", V(0.4f, 0.28f, 0.18f), 0.8f),
          make_material("foliage", V(0.25f, 0.5f, 0.2f), 0.7f)};
}

// The view a spec adopts unless it sets a camera: from above the corner of block 0 into the
// city, whatever its size (the fit to the bounds would show a city kilometres wide as a carpet).
SceneCamera corner_camera() {
  SceneCamera camera;
  camera.name = "street_corner";
  camera.position = V(-45.0f, 35.0f, -45.0f);
  camera.forward = V(2.0f, -1.0f, 2.0f) / 3.0f;  // down the diagonal, 19.5 degrees down
  return camera;
}

// Block i's centre on the street grid: blocks fill square shells around block 0 (shell s holds
// blocks s^2 to (s + 1)^2 - 1), so the city grows without knowing how many blocks it will have.
V block_centre(uint64_t i) {
  auto shell = uint64_t(std::sqrt(double(i)));  // exact below 2^52
  uint64_t k = i - shell * shell;
  uint64_t x = k < shell ? shell : k - shell, z = k < shell ? k : shell;
  return V(float(x) * kBlockPitch, 0, float(z) * kBlockPitch);
}

void add_building(const V& lot, Pcg32& rng, std::vector<Instance>& out) {
  uint32_t variant = rng.below(uint32_t(building_variants().size()));
  glm::mat3 turn = quarter_turn(rng.below(4));
  float width = 0.925f + 0.075f * rng.symmetric(), height = 1.0f + 0.15f * rng.symmetric();
  float dx = 0.5f * rng.symmetric(), dz = 0.5f * rng.symmetric();
  out.push_back(
      {kFirstBuilding + variant, placement(turn, V(width, height, width), lot + V(dx, 0, dz))});
}

// Along one side of a block (quarter_turn(side) faces its street): two lamps, a tree, a bench,
// and up to two cars parked either way round. Random numbers are drawn one statement at a time:
// the order in which a call's arguments are evaluated differs between compilers.
void add_street_props(const V& centre, uint32_t side, Pcg32& rng, std::vector<Instance>& out) {
  const glm::mat3 turn = quarter_turn(side);
  auto put = [&](uint32_t mesh, const glm::mat3& rotation, float scale, const V& at) {
    out.push_back({mesh, placement(rotation, V(scale), centre + turn * at)});
  };
  for (float t : {-12.0f, 12.0f}) put(kLamp, turn, 1.0f, V(t, kKerbHeight, kBlockHalf - 1.0f));
  float tree_scale = 1.0f + 0.2f * rng.symmetric(), tree_at = 2.0f * rng.symmetric();
  put(kTree, turn, tree_scale, V(tree_at, kKerbHeight, 22.0f));
  put(kBench, turn, 1.0f, V(rng.below(2) ? 6.0f : -6.0f, kKerbHeight, 22.5f));
  for (float slot : {-12.0f, 12.0f}) {
    if (rng.below(5) >= 3) continue;
    glm::mat3 heading = quarter_turn(side + 2 * rng.below(2));
    put(kCar, heading, 1.0f, V(slot + 3.0f * rng.symmetric(), 0, kParkingLane));
  }
}

// A block's instances: its street tile, a building on each lot, and the props of its sides.
void add_block(const V& centre, Pcg32& rng, std::vector<Instance>& out) {
  out.push_back({kStreetTile, placement(glm::mat3(1.0f), V(1.0f), centre)});
  for (uint32_t lot = 0; lot < 4; ++lot)
    add_building(centre + V(lot & 1 ? kLotOffset : -kLotOffset, kKerbHeight,
                            lot & 2 ? kLotOffset : -kLotOffset),
                 rng, out);
  for (uint32_t side = 0; side < 4; ++side) add_street_props(centre, side, rng, out);
}

}  // namespace

Scene make_city(const std::string& source, uint64_t triangles) {
  Scene scene;
  scene.source = source;
  scene.materials = city_materials();
  scene.object_names = {"buildings", "lamps", "cars", "benches", "trees", "ground"};
  scene.cameras = {corner_camera()};
  std::vector<UniqueMesh> meshes;
  for (UniqueMesh (*make)() : {make_lamp, make_car, make_bench, make_tree, make_street_tile})
    meshes.push_back(make());
  for (const BuildingVariant& variant : building_variants())
    meshes.push_back(make_building(variant));

  // Whole blocks until N instanced triangles; at least one.
  Pcg32 rng(kCitySeed);
  std::vector<Instance>& instances = scene.instanced.instances;
  uint64_t placed = 0;
  for (uint64_t block = 0; block == 0 || placed < triangles; ++block) {
    size_t first = instances.size();
    add_block(block_centre(block), rng, instances);
    for (size_t i = first; i < instances.size(); ++i)
      placed += meshes[instances[i].mesh].mesh.triangle_count();
  }
  keep_unique_meshes(std::move(meshes), scene);
  return scene;
}

}  // namespace rtsim::builtin
