// The paper's evaluation factor (§2.1): how far a vertex stands from the average plane of its
// neighbours. Small factor = little visual importance = removed first.
#pragma once

#include "base/geometry.h"
#include "base/positions.h"
#include "mesh/topology.h"
#include "vrs/simplify.h"

namespace vrs {

// Up to this valence every triple of neighbours defines a plane (C(10,3) = 120); above it a
// fixed subset of 2k triples spread around the ring keeps the cost linear in k.
constexpr int kAllTriplesValence = 10;
// cos(30°): a boundary vertex where the outline turns more than this is a corner, kept.
constexpr double kBoundaryCornerCos = 0.8660254037844387;

struct Evaluation {
  double factor = 0; // +inf when the vertex has no usable plane (it is then kept)
  Vec3 normal;       // unit normal of the plane the hole is projected on
  Vec3 fan_normal;   // unit area-weighted normal of the vertex's triangles
};

// The positions it reads are its base: a view the input-side classes take as well.
class Evaluator : public Positions {
 public:
  // `plane` is the mesh's own normal (Planar2D only).
  // `all_triples_valence`: up to which valence every triple is used (the benchmark and a
  // test vary it to measure what the subset changes).
  Evaluator(Mode mode, Vec3 plane, const float* positions,
            int all_triples_valence = kAllTriplesValence)
      : Positions(positions), mode_(mode), plane_(plane), all_triples_(all_triples_valence) {}

  // Outline corners: a boundary vertex whose outline turns more than acos(cos) is kept
  // (default kBoundaryCornerCos). -1: none is (the local-error price, and the factor's last
  // resort).
  void set_boundary_corner_cos(double cos) { corner_cos_ = cos; }

  // Factor of v with its ordered ring. `boundary_line` adds, for an open ring, the distance to
  // the line through its two boundary neighbours (the paper's two-neighbour factor).
  Evaluation evaluate(uint32_t v, const Ring& ring, bool boundary_line) const;

 private:
  Vec3 average_plane_normal(const Vec3* p, int k, Vec3 fan) const;

  Mode mode_;
  Vec3 plane_;
  int all_triples_;
  double corner_cos_ = kBoundaryCornerCos;
};

// Distance from p to the line through a and b (to a when a == b).
double distance_to_line(Vec3 p, Vec3 a, Vec3 b);

// The input surface's normal cone at each vertex, 4 floats a vertex: the unit normal (sum of
// the faces' unit normals; zero where none, or where the sum is shorter than kMinNormalSum:
// faces cancelling) and the sine of the largest angle between it and one of the vertex's faces
// (1 from 90 degrees up): 0 on a flat part, about 0.7 on a box's edge, 1 on a thin wall's rim.
constexpr double kMinNormalSum = 1e-3;
std::vector<float> vertex_normals(const std::vector<float>& positions,
                                  const std::vector<uint32_t>& triangles);
// One vertex's cone (4 floats at `cone`) from its faces in `topo`, and the sum of their areas
// (its fan's) at `fan_area` when given: what vertex_normals() computes for it, vertex by
// vertex, so that threads can share the vertices out.
void vertex_cone(const float* positions, const uint32_t* triangles, const Topology& topo,
                 uint32_t v, float* cone, float* fan_area);

// Unit normal of the whole mesh (area weighted), the plane of Planar2D.
Vec3 mesh_plane_normal(const float* positions, const std::vector<uint32_t>& triangles);

} // namespace vrs
