// The invariants a simplification must keep, measured on a (input, output, report) triple.
#pragma once

#include <string>

#include "vrs/simplify.h"

namespace vrs_test {

struct EdgeStats {
  size_t edges = 0, boundary = 0, nonmanifold = 0; // undirected edges by face count 1, > 2
  size_t referenced_vertices = 0;
  long euler() const; // V - E + F over referenced vertices
  size_t faces = 0;
};
EdgeStats edge_stats(const vrs::Mesh& m);

// All a simplification must always keep: report ok, indices valid, vertices a subset, no more
// non-manifold edges and no more repeated directed edges than the input had. "" when so.
std::string check_valid(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Report& r);

// Every output vertex is the input vertex the remap names, bit for bit, in input order, and
// every output face with a source is that input face.
std::string check_subset(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Report& r);
// No index out of range, no repeated corner.
std::string check_indices(const vrs::Mesh& m);
// Every boundary edge of the input (through the remap) is still a boundary edge of the output.
std::string check_boundary_kept(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Report& r);
// Triangles of quality < q (1 = equilateral).
size_t count_degenerate(const vrs::Mesh& m, double q = 1e-3);
// Output triangles whose normal opposes the input's area-weighted vertex normals at its corners.
size_t count_flipped(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Report& r);
// Each directed edge used at most once (consistent orientation).
size_t count_duplicate_directed_edges(const vrs::Mesh& m);

} // namespace vrs_test
