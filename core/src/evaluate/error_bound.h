// A certified bound of the symmetric Hausdorff distance between the simplified surface and the
// input (Options::max_error), after Klein, Liebich & Straßer, "Mesh reduction with error
// control" (1996): every face f carries e_f such that each point of f lies within e_f of the
// input, and the input is covered by regions R_f each within e_f of the output. Then the
// Hausdorff distance is at most the largest e_f. Input faces start at 0.
//
// A removal replaces the old fan by a patch over the same ring. Both project one-to-one on the
// plan's plane (checked here), so a point x of that plane has one point P(x) on the patch and
// one F(x) on the fan, and the pieces where both are affine are the convex cells of the two
// triangulations' overlay: |P(x) - F(x)| is convex on each cell, its maximum is at a cell's
// corners. A new triangle t then gets max over the old faces f it overlaps of
// (max |P - F| on t ∩ f) + e_f. An open ring's cut-off corner (the triangle between v and its
// two border neighbours) has no patch over it: its points are priced by their distance to the
// new border edge, which the triangle on that edge answers for.
#pragma once

#include "fill/triangulation.h"
#include "mesh/topology.h"

namespace vrs {

// Writes each new triangle's bound into patch.bound (rounded up to float) and returns true;
// false when the patch cannot be certified (the fan or the patch do not project one-to-one on
// the plan's plane, a triangle cut off). An open ring is a border's (a seam's sides are bounded
// together, as one ring). `face_bound` holds e_f per face slot; `c` is the removed vertex's
// position.
bool bound_patch(const Ring& ring, Patch& patch, Vec3 c, const float* face_bound);

} // namespace vrs
