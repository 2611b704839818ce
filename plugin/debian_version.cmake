# Read by cpack (CPACK_PROJECT_CONFIG_FILE): scripts/build_debs.sh packs one component per run,
# whose version then names its Debian release, e.g. 0.1.0~sid.
list(LENGTH CPACK_COMPONENTS_ALL n)
if(n EQUAL 1)
  string(TOUPPER "${CPACK_COMPONENTS_ALL}" c)
  set(CPACK_DEBIAN_PACKAGE_VERSION "${CPACK_PACKAGE_VERSION}~${CPACK_DEBIAN_${c}_SUITE}")
endif()
