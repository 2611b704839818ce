// Fold-overs: output faces turned against the surface they stand for. The core's vetoes look
// only at the faces a removal replaces; this looks at the input itself, so drift over many
// removals is caught too.
#pragma once

#include <cstddef>

#include "vrs/simplify.h"

namespace vrs_test {

// New output faces (face_source kRemoved) facing against every input face near them: the
// input faces within (distance of the nearest one + half the output face's longest edge) of its
// centroid all turn more than 90° from it. A thin part whose far side is nearer than the face's
// own size is not a fold (one of the faces in reach agrees); a face turned over on its own
// surface is.
size_t count_fold_overs(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Report& r);

// The benchmark's measure, per face: output faces turned more than 90° from the input face
// nearest their centroid (where several are nearest, one agreeing is enough). Stricter than
// count_fold_overs: a face across a thin part, nearer its far side, counts.
size_t count_faces_against_nearest_input(const vrs::Mesh& in, const vrs::Mesh& out);

} // namespace vrs_test
