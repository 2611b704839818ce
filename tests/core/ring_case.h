// A vertex's ring on a small mesh, and its projection: the set-up of the planning pieces'
// tests (candidates, vetoes).
#pragma once

#include <vector>

#include "evaluate/evaluation.h"
#include "fill/triangulation.h"
#include "mesh/topology.h"

struct RingCase {
  vrs::Mesh mesh;
  vrs::Topology topo;
  vrs::Ring ring;
  std::vector<float> normals; // the input's normal cones (4 floats a vertex), as the driver's
};

// Builds the topology, the ring of `v` and the vertex normals of `s.mesh`.
inline void open_ring(RingCase& s, uint32_t v) {
  s.topo.build(s.mesh.triangles, s.mesh.vertex_count());
  s.topo.ring(v, s.mesh.triangles.data(), 64, s.ring);
  s.normals = vrs::vertex_normals(s.mesh.positions, s.mesh.triangles);
}

// The ring of `v` projected along `n`, as the planner projects it (no triangles yet).
inline vrs::Patch projected(const RingCase& s, uint32_t v, vrs::Vec3 n) {
  vrs::Patch p;
  vrs::plane_basis(n, p.u, p.w);
  p.normal = n;
  const float* x = s.mesh.positions.data();
  for (int i = 0; i < s.ring.verts; ++i) {
    const uint32_t u = s.ring.v[i];
    p.q[i] = {x[3 * u], x[3 * u + 1], x[3 * u + 2]};
    vrs::Vec3 d = p.q[i] - vrs::Vec3{x[3 * v], x[3 * v + 1], x[3 * v + 2]};
    p.p[i] = {dot(d, p.u), dot(d, p.w)};
  }
  vrs::set_replaced_faces({x[3 * v], x[3 * v + 1], x[3 * v + 2]}, s.ring, p);
  return p;
}
