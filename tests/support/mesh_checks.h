// The invariants a simplification must keep, measured on a (input, output, report) triple.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

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
// Output triangles whose normal opposes the input's vertex normals (sums of unit face normals)
// at its corners.
size_t count_flipped(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Report& r);
// Each directed edge used at most once (consistent orientation).
size_t count_duplicate_directed_edges(const vrs::Mesh& m);

// Output triangles made by the re-triangulation (face_source kRemoved) that clearly oppose the
// input's vertex normals at their corners (untouched input faces are the user's business).
size_t count_flipped_new(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Report& r);
// Euler characteristic V - E + F of each connected component (over referenced vertices),
// sorted, fans that touch only at a vertex counted apart (the core simplifies them apart):
// removals must leave every component's topology as it was.
std::vector<long> component_euler(const vrs::Mesh& m);
// The same for a run's input and output, fans apart only where they are apart in the input
// (a vertex whose edge of three faces a removal took away is not split in the output either).
bool same_component_euler(const vrs::Mesh& in, const vrs::Mesh& out,
                          const std::vector<uint32_t>& remap);
// Same positions bit for bit (NaN included) and same triangles.
bool same_bits(const vrs::Mesh& a, const vrs::Mesh& b);
// Edges by their two end positions (lower first), counted over the faces: a surface closed by
// position has every one twice, however its vertices are split.
std::map<std::array<float, 6>, int> edges_by_position(const vrs::Mesh& m);
// Reverses faces so that neighbours agree on the orientation (each connected piece keeps the
// one most of its faces had): the reference for the core's Report::reoriented_faces. Returns
// the number reversed.
size_t orient_coherently(vrs::Mesh& m);
// The input without faces that repeat a corner (the core drops them first).
vrs::Mesh without_repeated_corner_faces(const vrs::Mesh& m);

// With Options::corner_sources: every output corner's source is an input corner of the same
// vertex, and, with constrained edges given, the three corners of every output face come from
// one chart (input faces connected across edges that are not constrained). "" when so.
std::string check_corner_sources(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Options& o,
                                 const vrs::Report& r);

// Every invariant of one run, for any input (the fuzzer's and the sweep's): a refusal leaves
// the mesh as given and says why; otherwise valid indices, a vertex subset, no new non-manifold
// or boundary edges, no new degenerate faces, no flipped new faces, each component's Euler
// characteristic unchanged, the boundary kept unless asked otherwise, the report's counts
// true, and the target reached or the stop reason consistent with it. "" when all hold.
std::string check_run(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Options& o,
                      const vrs::Report& r);

// Whether a run stopped short of a count target for one of the faithful reasons: every filling
// left would fold the surface over, or the next removal would change the surface abruptly (a
// price jump).
bool stops_faithfully(const vrs::Report& r);

// Determinism: simplifying `in` with `o` again, on another thread count (1 or 2), must give
// `first` bit for bit and the same stop reason and removals as `first_report`. "" when so.
std::string check_rerun(const vrs::Mesh& in, const vrs::Options& o, const vrs::Mesh& first,
                        const vrs::Report& first_report);

} // namespace vrs_test
