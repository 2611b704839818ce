// CMeshO (MeshLab's vcglib mesh) <-> the core mesh. Nothing here decides anything about the
// simplification; it only copies, and writes a finished result back in one step.
#pragma once

#include "meshlab_compat.h"

#include <string>
#include <vector>

#include "vcg_corner_data.h"
#include "vrs/simplify.h"

namespace vrs_plugin {

// The live (not deleted) part of a CMeshO as a core mesh.
struct CoreCopy {
  vrs::Mesh mesh;
  std::vector<CVertexO*> vertex; // core vertex index -> CMeshO vertex
  std::vector<uint32_t> index;   // CMeshO vertex index -> core index (kRemoved: deleted)
  std::vector<size_t> face;      // core face index -> index in CMeshO::face (which may move)
};
CoreCopy to_core(CMeshO& m);

// Per-vertex locks (empty when none): the ends of the layer's edges (an OBJ's `l` polylines;
// removing one would leave an edge pointing at a deleted vertex), and with "Selected" every
// vertex of an unselected face (a vertex may go only if every face around it is selected, as
// Quadric Edge Collapse Decimation does).
std::vector<uint8_t> vertex_locks(const CMeshO& m, const CoreCopy& copy, bool selected_only);

// Per core face, whether it is part of a polygon (a faux edge joins it to another triangle):
// polygons are written back whole, so the core's slide leaves them as they are. Empty when
// the layer has none.
std::vector<uint8_t> polygon_faces(const CMeshO& m, const CoreCopy& copy);

// The per-corner and per-face data the layer holds (texture coordinates, normals, colors).
// `feature_angle` (degrees, 0: off) is also the crease angle of per-corner normals.
vrs_vcg::CornerData corner_data(const MeshModel& m, double feature_angle);

// Edges across which that data differs: the core keeps them (constrained edges).
std::vector<uint32_t> seams(const CMeshO& m, const CoreCopy& copy, const vrs_vcg::CornerData& d);

// Writes the simplified mesh back: removed vertices are deleted, faces the core left untouched
// keep every attribute, new faces are added (selected when `select_new_faces`) with the corner
// and face data of the input corners the report names, then the mesh is compacted. Call only
// with a successful report.
void apply(CMeshO& m, const CoreCopy& copy, const vrs::Mesh& simplified, const vrs::Report& r,
           bool select_new_faces, const vrs_vcg::CornerData& d);

} // namespace vrs_plugin
