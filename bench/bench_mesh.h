// The vcglib mesh the benchmark hands to MeshLab's quadric decimation and to the surface-error
// measure, with the components both need, and its conversion from and to the plain mesh.
#pragma once

#include <vcg/complex/complex.h>

#include "vrs/simplify.h"

namespace vrs_bench {

class BVertex;
class BFace;
struct BTypes
    : public vcg::UsedTypes<vcg::Use<BVertex>::AsVertexType, vcg::Use<BFace>::AsFaceType> {};
class BVertex
    : public vcg::Vertex<BTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::VFAdj,
                         vcg::vertex::Mark, vcg::vertex::Qualityf, vcg::vertex::BitFlags> {};
class BFace : public vcg::Face<BTypes, vcg::face::VertexRef, vcg::face::VFAdj, vcg::face::Normal3f,
                               vcg::face::Mark, vcg::face::BitFlags> {};
class BenchMesh : public vcg::tri::TriMesh<std::vector<BVertex>, std::vector<BFace>> {};

void to_vcg(const vrs::Mesh& in, BenchMesh& out);
vrs::Mesh from_vcg(const BenchMesh& m); // live elements only, in order

} // namespace vrs_bench
