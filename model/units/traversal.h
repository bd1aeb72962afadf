// Traversal unit: walks one ray through the BVH image, one node visit or one leaf per step(),
// so the timing model can drive exactly this code and charge each step's fetches and unit
// passes. Ordered stack traversal as in pbrt's BVH accelerator and Ylitie et al. (HPG 2017):
// at a node the ray-box unit tests every child, the hit children are sorted by entry distance
// and pushed far-to-near, so the nearest is visited next; a popped entry farther than the
// closest hit so far is dropped without a fetch. Any-hit queries stop at the first hit.
// Timing assumptions (for the timing model): one node step = one node fetch + one ray-box unit
// pass + a sort of at most `width` distances; one leaf step = one fetch and one ray-triangle
// unit pass per triangle. This file itself has no notion of time.
// Two levels (model/bvh/two_level.h): a top-level leaf is an instance step: one instance record
// fetch and one pass of the transform unit, which moves the ray into the instance's object
// space and enters its BLAS at the root; a marker below the BLAS's entries on the stack moves
// the ray back when they are done. An instance whose mask shares no bit with the ray type's
// inclusion mask is skipped after its record is read, without a transform. Animated instances:
// a ray starts in its frame's top level. t keeps its meaning across levels (an affine map preserves
// the ray's parameter), so the closest hit so far bounds both.
// Alpha-tested triangles (traces/alpha.h): a candidate hit on one is an any-hit call (counted,
// its texel's address kept in state.texels for the timing model), dropped where the mask has a
// hole; the ray goes on as if the triangle were not there.
#pragma once

#include <cstdint>
#include <vector>

#include "model/bvh/bvh_image.h"
#include "model/bvh/two_level.h"
#include "model/units/prepared_ray.h"
#include "traces/ray.h"

namespace rtsim {

struct TraversalConfig {
  float box_padding = 0x1p-20f;  // relative: box growth per |origin| + scene extent (ray_box.h)
  // Keep each ray's fetch list, one entry per node, triangle or instance record (L2 warming
  // reads it); a step's one contiguous read is in its StepResult either way.
  bool record_accesses = true;
};

// The config of a unit whose users read each step's one read from its StepResult (the timing
// models), with no fetch list to keep.
inline TraversalConfig without_fetch_list() {
  TraversalConfig config;
  config.record_accesses = false;
  return config;
}

// Per-ray counters under Embree's names.
struct TraversalCounters {
  uint64_t trav_nodes = 0;        // node visits (node fetches)
  uint64_t trav_leaves = 0;       // leaf visits
  uint64_t trav_prims = 0;        // ray-triangle tests
  uint64_t trav_prim_hits = 0;    // tests that hit (in range, before later ones shortened it)
  uint64_t trav_instances = 0;    // instance transforms (two levels: BLAS entries)
  uint64_t trav_alpha_tests = 0;  // candidate hits on alpha-tested triangles (traces/alpha.h)

  TraversalCounters& operator+=(const TraversalCounters& o);
};

enum class AccessKind : uint8_t { Node, Triangle, Instance };

struct MemoryAccess {
  uint64_t address = 0;
  uint32_t bytes = 0;
  AccessKind kind = AccessKind::Node;
};

// A stack entry whose count is this moves the ray back to world space (two levels).
constexpr uint32_t kLeaveInstance = ~0u;

struct StackEntry {
  uint32_t index = 0;  // node position, or first triangle (instance record) position of a leaf
  uint32_t count = 0;  // triangles of a leaf; 0 for a node; kLeaveInstance
  float tnear = 0.0f;  // where the ray enters the box (prepared-ray units)
};

// Everything one ray in flight holds. Reuse one state for many rays: begin() resets it and keeps
// the vectors' capacity. What every step touches comes first, the second level's world-space
// ray last: a timed run keeps thousands of states, and a step's host cache misses grow with
// the lines it touches.
struct TraversalState {
  PreparedRay ray;
  Query query = Query::ClosestHit;
  bool force_opaque = false;  // the ray's: no any-hit alpha tests
  bool done = true;
  uint8_t mask = kAllInstances;  // the ray type's inclusion mask (two levels)
  float t_hit = 0.0f;            // closest hit so far, or tmax (prepared-ray units)
  uint32_t prim = kNoHit;        // triangle hit (also for any-hit queries)
  float u = 0.0f, v = 0.0f;
  // Two levels: the level walked now and the ray's frame's top level.
  const BvhImage* level = nullptr;
  const BvhImage* top = nullptr;
  std::vector<StackEntry> stack;
  uint32_t max_stack = 0;  // deepest the stack got, in entries
  TraversalCounters counters;
  std::vector<MemoryAccess> accesses;  // this ray's fetches, in order
  // The texel addresses of its any-hit calls (alpha-tested candidates), in order; the shader
  // core reads them, not the traversal, so they are kept apart from `accesses`.
  std::vector<uint64_t> texels;
  // Two levels: the world-space ray while in a BLAS, the closest hit so far when the instance
  // was entered, the instance being walked and the one hit.
  PreparedRay world;
  float world_t_hit = 0.0f;
  uint32_t instance = kNoHit, hit_instance = kNoHit;
};

enum class StepKind : uint8_t { Node, Leaf, Instance, Done };

struct StepResult {
  StepKind kind = StepKind::Done;
  uint32_t first_access = 0;  // this step's fetches: state.accesses[first, first + count)
  uint32_t access_count = 0;  // (with record_accesses; else 0)
  uint32_t tests = 0;         // boxes (node) or triangles (leaf) tested; 1 transform (instance)
  uint32_t hits = 0;          // boxes entered, or triangles hit
  uint32_t anyhit_calls = 0;  // leaf: candidates on alpha-tested triangles (state.texels' last)
  // The one read the step makes (a node; a leaf's triangles it tested, which lie together; an
  // instance record); fetch_bytes 0: none.
  uint64_t fetch_address = 0;
  uint32_t fetch_bytes = 0;
};

class TraversalUnit {
 public:
  // One level, or two (starts at the top level; hits name the instance and its mesh's
  // triangle).
  explicit TraversalUnit(BvhView bvh, TraversalConfig config = {});

  // Starts a ray: the root node is the first thing on the stack.
  void begin(TraversalState& state, const Ray& ray) const;
  // Visits the next node or leaf; Done (with no fetch) when the ray is finished.
  StepResult step(TraversalState& state) const;
  // What a step makes of a stack entry (not a kLeaveInstance mark) in the level the ray is in
  // (at_top: a two-level BVH's top level, whose leaves are instances).
  StepKind kind_of(const StackEntry& entry, bool at_top) const {
    return entry.count == 0             ? StepKind::Node
           : at_top && bvh_.two_level() ? StepKind::Instance
                                        : StepKind::Leaf;
  }
  // Asks the host to bring what the next step likely reads (the node or triangles on top of the
  // stack) into its caches, for a step that comes later; changes nothing modelled.
  void prime(const TraversalState& state) const;
  // The ray's answer as EmbreeScene::trace gives it: any-hit reports prim kAnyPrim, t = tmax.
  Hit result(const TraversalState& state, const Ray& ray) const;
  // begin, step until Done, result.
  Hit trace(TraversalState& state, const Ray& ray) const;
  // Two levels, in an instance: the closest hit so far in world units, as leaving it sets it.
  static float world_t_hit(const TraversalState& state);

  const BvhView& bvh() const { return bvh_; }
  const TraversalConfig& config() const { return config_; }

 private:
  StepResult visit_node(TraversalState& state, const StackEntry& entry) const;
  StepResult visit_leaf(TraversalState& state, const StackEntry& entry) const;
  StepResult visit_instance(TraversalState& state, const StackEntry& entry) const;
  void leave_instance(TraversalState& state) const;
  // Appends one fetch to the ray's access list, field by field (no 16-byte temporary).
  static void record(TraversalState& state, uint64_t address, uint32_t bytes, AccessKind kind);

  BvhView bvh_;
  TraversalConfig config_;
};

}  // namespace rtsim
