# FindMED — the MED-fichier C library (Debian: libmedc-dev), for the MED plug-in
# (plugins/med). Debian builds MED with MPI, so med.h needs HDF5's OpenMPI headers
# (hdf5/openmpi/hdf5.h) and OpenMPI's mpi.h; only the plug-in's ABI check includes it.
# Provides MED::MED (library and include folders).
find_path(MED_INCLUDE_DIR med.h)
find_library(MED_LIBRARY NAMES medC)
find_path(MED_HDF5_INCLUDE_DIR hdf5.h PATH_SUFFIXES hdf5/openmpi hdf5/mpich hdf5/serial)
find_path(MED_MPI_INCLUDE_DIR mpi.h
  PATH_SUFFIXES ${CMAKE_LIBRARY_ARCHITECTURE}/mpi mpi openmpi
  PATHS /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/openmpi/include)
if(NOT MED_INCLUDE_DIR OR NOT MED_LIBRARY OR NOT MED_HDF5_INCLUDE_DIR OR NOT MED_MPI_INCLUDE_DIR)
  message(FATAL_ERROR "parasol needs the MED library for FORMAT='MED' "
    "(med.h: ${MED_INCLUDE_DIR}, libmedC: ${MED_LIBRARY}, hdf5.h: ${MED_HDF5_INCLUDE_DIR}, "
    "mpi.h: ${MED_MPI_INCLUDE_DIR}): apt-get install libmedc-dev")
endif()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(MED DEFAULT_MSG MED_LIBRARY MED_INCLUDE_DIR)
if(MED_FOUND AND NOT TARGET MED::MED)
  add_library(MED::MED UNKNOWN IMPORTED)
  set_target_properties(MED::MED PROPERTIES IMPORTED_LOCATION ${MED_LIBRARY}
    INTERFACE_INCLUDE_DIRECTORIES
      "${MED_INCLUDE_DIR};${MED_HDF5_INCLUDE_DIR};${MED_MPI_INCLUDE_DIR}")
endif()
