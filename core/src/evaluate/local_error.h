// The second evaluation the hash table can sort by: how far the re-triangulated hole would
// stand from the surface it replaces (a local, two-sided Hausdorff estimate). The paper's
// factor looks only at the vertex; this looks at the patch that would really be made.
#pragma once

#include <vector>

#include "base/distance.h"
#include "evaluate/evaluation.h"
#include "fill/triangulation.h"
#include "mesh/topology.h"

namespace vrs {

class Workers;

// The fan of triangles around a removed vertex, as planned (`patch` holds the ring's positions,
// its projection and the replaced faces, set_replaced_faces): squared distances from points of a
// new patch to it.
class OldFan {
 public:
  OldFan(uint32_t v, const Ring& ring, const Patch& patch, const Evaluator& eval);
  double distance2(Vec3 x) const;
  // Whether every face within (the nearest one's distance + `slack`) of x turns more than 90°
  // from the unit normal n: x's neighbourhood of the old fan faces against n.
  bool opposes_near(Vec3 x, Vec3 n, double slack) const;
  double area() const { return area_; }

 private:
  double to_face2(Vec3 x, int i, double best) const; // min(best, distance^2 to face i)
  const Ring& ring_;
  const Patch& patch_;
  Vec3 c_;
  double area_ = 0;
  const UnsetArray<Vec3, kMaxRing>& n_; // unit normals: the plane distance skips most queries
};

// Squared distance to the old fan of the new triangle (a, b, c) (ring positions): the largest
// of its centroid's and its new edges' midpoints' (patch_error's terms for one triangle).
double triangle_error2(const OldFan& fan, const Ring& ring, const Patch& patch, int a, int b,
                       int c);

// Largest of: the removed vertex's distance to the new patch, and the distance of each new
// triangle's centroid and each new diagonal's midpoint to the old fan (zero for a flat ring),
// weighted by sqrt(fan area / reference_area): the same offset over a wider patch moves more
// surface. On the benchmark's 18 real cases the weight took the geometric mean of our mean
// error over QECD's from 1.64 to 1.41 (exponents 0.25 and 0.75 measured worse).
// Where a corner lies on a crease of the input (kCornerOnCrease: a crease, a rim, a thin wall)
// the farthest point misjudges what moves: a fillet's middle dropped is far but moves a sliver, a
// wall tilted by its foot is near but moves the wall. There the price is at least the geometric
// mean of that and the surface moved (moved_surface / reference_area), which grows with the
// patch's size as the local price does, so price jumps keep their meaning.
double patch_error(uint32_t v, const Ring& ring, const Patch& patch, const Evaluator& eval,
                   double reference_area);

// The surface moved by the patch, two-sided: the area-weighted distance of the old fan to the
// new patch (two points per old face) plus that of the new patch to the old fan (its
// triangles' centroids); a distance times an area.
// `centroid2`: the new triangles' centroids' squared distances to the old fan, when the caller
// has measured them already (patch_error has).
double moved_surface(const OldFan& fan, const Ring& ring, const Patch& patch, Vec3 c,
                     const double* centroid2 = nullptr);

// How far v drops onto the planes of the patch's triangles, at most: an O(k) estimate of
// patch_error's main term, used to rank the ways to fill one hole (same weight for all).
// With a `cap`, it may stop once over it: `complete` false, the height so far (a lower bound).
double drop_height(uint32_t v, const Patch& patch, const Evaluator& eval);
double drop_height(uint32_t v, const Patch& patch, const Evaluator& eval, double cap,
                   bool& complete);

// Mean area of the finite triangles (1 when there is none): the weight's reference.
double mean_triangle_area(const float* positions, const std::vector<uint32_t>& triangles,
                          Workers* workers = nullptr);

} // namespace vrs
