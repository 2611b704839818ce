# Debian packages of the filter, one per MeshLab it is built for, each depending on that exact
# MeshLab (a host refuses a plugin built for another version): scripts/build_debs.sh runs
# `cpack -G DEB` once per component into dist/:
#   meshlab-filter-vertex-removal_<v>~bookworm_amd64.deb   MeshLab 2020.09 (Debian 12)
#   meshlab-filter-vertex-removal_<v>~trixie_amd64.deb     MeshLab 2022.02 (Debian 13)
#   meshlab-filter-vertex-removal_<v>~sid_amd64.deb        MeshLab 2025.07 (Debian unstable)
# The exact MeshLab version comes from the dpkg database of the system the plugin was linked
# against (this machine's, or the trixie/sid root's).
set(vrs_deb_components "")
function(vrs_debian_package component suite admindir)
  if(NOT TARGET ${ARGN})
    return()
  endif()
  execute_process(COMMAND dpkg-query --admindir=${admindir} -W -f=\${Version} meshlab
                  OUTPUT_VARIABLE meshlab_version RESULT_VARIABLE failed ERROR_QUIET)
  if(failed OR NOT meshlab_version)
    message(STATUS "No meshlab package in ${admindir}: no Debian package for ${component}")
    return()
  endif()
  string(TOUPPER ${component} c)
  set(CPACK_DEBIAN_${c}_PACKAGE_NAME meshlab-filter-vertex-removal PARENT_SCOPE)
  set(CPACK_DEBIAN_${c}_PACKAGE_DEPENDS "meshlab (= ${meshlab_version})" PARENT_SCOPE)
  set(CPACK_DEBIAN_${c}_FILE_NAME
      "meshlab-filter-vertex-removal_${PROJECT_VERSION}~${suite}_amd64.deb" PARENT_SCOPE)
  set(VRS_DEB_SUITE_${component} ${suite} PARENT_SCOPE)
  # The package's copyright file (GPL-3.0), in the package only.
  install(FILES "${PROJECT_SOURCE_DIR}/LICENSE" DESTINATION /usr/share/doc/meshlab-filter-vertex-removal
          RENAME copyright COMPONENT ${component} EXCLUDE_FROM_ALL)
  set(vrs_deb_components ${vrs_deb_components} ${component} PARENT_SCOPE)
endfunction()

vrs_debian_package(meshlab2020 bookworm /var/lib/dpkg filter_vertex_removal)
if(VRS_MESHLAB2022_LIBDIR)
  vrs_debian_package(meshlab2022 trixie "${VRS_MESHLAB2022_LIBDIR}/../../../../var/lib/dpkg"
                     filter_vertex_removal_2022)
endif()
if(VRS_MESHLAB2025_LIBDIR)
  vrs_debian_package(meshlab2025 sid "${VRS_MESHLAB2025_LIBDIR}/../../../../var/lib/dpkg"
                     filter_vertex_removal_2025)
endif()
set(VRS_DEB_COMPONENTS ${vrs_deb_components} CACHE INTERNAL "components with a Debian package")

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME meshlab-filter-vertex-removal)
set(CPACK_PACKAGE_VENDOR vrsimplify)
set(CPACK_PACKAGE_CONTACT "vrsimplify developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "MeshLab filter: Simplification: Vertex Removal Decimation (vrsimplify)")
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "Vertex-removal mesh simplification (Pivec & Domiter) as a MeshLab filter.\n The output's vertices are input vertices, untouched: every attribute survives\n exactly. Adds Filters > Remeshing, Simplification and Reconstruction >\n Simplification: Vertex Removal Decimation, also in meshlabserver scripts.")
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEB_COMPONENT_INSTALL ON)
# The plugin's install destination is absolute (where MeshLab looks): the package holds it there.
# Per component: the version names the Debian release it is for (read when cpack runs).
set(CPACK_PROJECT_CONFIG_FILE "${CMAKE_CURRENT_LIST_DIR}/debian_version.cmake")
foreach(component ${vrs_deb_components})
  string(TOUPPER ${component} c)
  set(CPACK_DEBIAN_${c}_SUITE ${VRS_DEB_SUITE_${component}})
endforeach()
include(CPack)
