// The input behind today's faces: every removed vertex is carried by the face of today's mesh
// that stands nearest it, so a removal can be judged against the input the old fan stood for
// (a fold-over against the input, not against faces that may already lean far from it).
// Pricing by the farthest carried vertex too was measured: no better tail for more time
// (bench/ablation.md); it is not done.
#pragma once

#include <cstdint>
#include <vector>

#include "base/positions.h"
#include "base/workers.h"
#include "fill/triangulation.h"
#include "mesh/topology.h"

namespace vrs {

class CarriedPoints {
 public:
  void init(size_t face_slots, size_t vertices, Workers* workers = nullptr) {
    fill_on(workers, head_, face_slots, kNone);
    fill_on(workers, next_, vertices, kNone);
  }
  bool active() const { return !head_.empty(); }

  // After v's removal wrote the patch into the ring's face slots (new triangle i in slot
  // ring.f[i]): the old faces' points and v go to the new triangle nearest each. Touches only
  // the ring's slots and those points: removals of a batch hand over in parallel.
  void hand_over(uint32_t v, const Ring& ring, const Patch& patch, const Positions& eval);

  // Each point the ring's faces carry.
  template <class Fn> void for_each(const Ring& ring, Fn&& fn) const {
    for_each_by_face(ring, [&](int, uint32_t p) { fn(p); });
  }
  // The same, with the ring's face (its index in ring.f) that carries each.
  template <class Fn> void for_each_by_face(const Ring& ring, Fn&& fn) const {
    for (int i = 0; i < ring.faces; ++i)
      for (uint32_t p = head_[ring.f[i]]; p != kNone; p = next_[p])
        fn(i, p);
  }
  // v gave its place to u (a point the ring's faces carried): v is carried, u no longer; each
  // point goes to the fan's triangle (in the ring's slots) nearest it.
  void slide(uint32_t v, uint32_t u, const Ring& ring, const Patch& fan, const Positions& eval);

  // Whether a new triangle turns over against the input surface it stands for: of the points
  // the ring's faces carry, and v, each one that projects (along the plan's normal) into a new
  // triangle must lie where that triangle faces the input's side, within the input's normal
  // cone there (`cones`: vertex_normals(), 4 floats a vertex). The old faces only stand for
  // the input; after many removals they can lean far from it, and a fold-over is judged
  // against the input.
  bool folds_input(uint32_t v, const Ring& ring, const Patch& patch, const Positions& eval,
                   const float* cones) const;

 private:
  // One chain of every point the ring's faces carry but `skip`, v first; the slots emptied.
  uint32_t gather(uint32_t v, const Ring& ring, uint32_t skip);
  UninitVector<uint32_t> head_; // per face slot: the first point it carries, or kNone
  UninitVector<uint32_t> next_; // per vertex: the next point of the same face, or kNone
};

} // namespace vrs
