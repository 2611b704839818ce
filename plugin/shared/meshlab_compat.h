// The few names that differ between MeshLab's two plugin APIs: 2020.09 (MeshFilterInterface)
// and 2022.02 and later (FilterPlugin; 2025.07 and pymeshlab too). Everything shared includes
// MeshLab through this header only; VRS_MESHLAB_API (2020 or 2022) is set by the build target.
#pragma once

#if !defined(VRS_MESHLAB_API)
#error "VRS_MESHLAB_API must be 2020 or 2022 (set by plugin/CMakeLists.txt)"
#endif

#if VRS_MESHLAB_API >= 2022
#include <common/GLLogStream.h>
#include <common/ml_document/mesh_document.h>
#include <common/parameters/rich_parameter_list.h>
#else
#include <common/GLLogStream.h>
#include <common/filter_parameter/rich_parameter_list.h>
#include <common/meshmodel.h>
#endif

namespace vrs_plugin {

// MeshLab 2020.09's meshlabserver aborts a script that lacks one of a filter's parameters, so a
// parameter added later would break every .mlx written for it: new parameters go to 2022+ only.
constexpr bool kScriptsListEveryParameter = VRS_MESHLAB_API < 2022;

inline void delete_layer(MeshDocument& md, MeshModel* m) {
#if VRS_MESHLAB_API >= 2022
  md.delMesh(m->id());
#else
  md.delMesh(m);
#endif
}

inline void update_box_and_normals(MeshModel& m) {
#if VRS_MESHLAB_API >= 2022
  m.updateBoxAndNormals();
#else
  m.UpdateBoxAndNormals();
#endif
}

} // namespace vrs_plugin
