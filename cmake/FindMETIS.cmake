# FindMETIS — METIS graph partitioning (Debian: libmetis-dev, 32-bit idx_t).
# Provides METIS::METIS.
find_path(METIS_INCLUDE_DIR metis.h PATH_SUFFIXES metis)
find_library(METIS_LIBRARY NAMES metis)
if(NOT METIS_INCLUDE_DIR OR NOT METIS_LIBRARY)
  message(FATAL_ERROR "parasol needs METIS: apt-get install libmetis-dev")
endif()
file(STRINGS ${METIS_INCLUDE_DIR}/metis.h _metis_idx REGEX "^#define IDXTYPEWIDTH")
string(REGEX MATCH "[0-9]+" METIS_IDXTYPEWIDTH "${_metis_idx}")
if(NOT METIS_IDXTYPEWIDTH STREQUAL "32")
  message(FATAL_ERROR "parasol's METIS binding expects 32-bit idx_t; metis.h has ${METIS_IDXTYPEWIDTH}")
endif()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(METIS DEFAULT_MSG METIS_LIBRARY METIS_INCLUDE_DIR)
if(METIS_FOUND AND NOT TARGET METIS::METIS)
  add_library(METIS::METIS UNKNOWN IMPORTED)
  set_target_properties(METIS::METIS PROPERTIES IMPORTED_LOCATION ${METIS_LIBRARY}
    INTERFACE_INCLUDE_DIRECTORIES ${METIS_INCLUDE_DIR})
endif()
