# Solver back-end plug-ins (src/solvers/cholmod_solver.f90, mumps_solver.f90 open them with
# dlopen on first use): libparasol_cholmod.so (METHODE='MULT_FRONT', CHOLMOD from Debian's
# libsuitesparse-dev) and libparasol_mumps.so (METHODE='MUMPS', Debian's libmumps-seq-dev,
# or with PARASOL_MUMPS_MPI=ON the MPI MUMPS of libmumps-dev and OpenMPI). They are built
# into <build>/lib/parasol and installed into <prefix>/lib/parasol; parasol itself never
# links them, so a deck that does not ask for them starts without loading them.
# Needs PARASOL_BUILD_PLUGIN_DIR and PARASOL_INSTALL_PLUGINDIR (CMakeLists.txt).

option(PARASOL_MUMPS_MPI "Build the MUMPS plug-in against MPI MUMPS (libmumps-dev, OpenMPI): \
mpirun -np N parasol deck factors over N processes" OFF)

# ---- CHOLMOD ----------------------------------------------------------------------------
find_path(PARASOL_CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(PARASOL_CHOLMOD_LIBRARY NAMES cholmod)
if(NOT PARASOL_CHOLMOD_INCLUDE_DIR OR NOT PARASOL_CHOLMOD_LIBRARY)
  message(FATAL_ERROR "parasol's MULT_FRONT back-end needs CHOLMOD: apt-get install "
                      "libsuitesparse-dev")
endif()
add_library(parasol_cholmod MODULE ${PROJECT_SOURCE_DIR}/plugins/cholmod/parasol_cholmod.c)
target_include_directories(parasol_cholmod PRIVATE ${PARASOL_CHOLMOD_INCLUDE_DIR}/..)
target_link_libraries(parasol_cholmod PRIVATE ${PARASOL_CHOLMOD_LIBRARY})
target_compile_options(parasol_cholmod PRIVATE -Wall -Wextra $<$<CONFIG:Debug>:-Werror>)

# ---- MUMPS ------------------------------------------------------------------------------
find_path(PARASOL_MUMPS_INCLUDE_DIR dmumps_struc.h)
if(NOT PARASOL_MUMPS_INCLUDE_DIR)
  message(FATAL_ERROR "parasol's MUMPS back-end needs MUMPS's headers: apt-get install "
                      "libmumps-seq-dev (or libmumps-dev with -DPARASOL_MUMPS_MPI=ON)")
endif()
add_library(parasol_mumps MODULE ${PROJECT_SOURCE_DIR}/plugins/mumps/parasol_mumps.F90)
set_target_properties(parasol_mumps PROPERTIES
  Fortran_MODULE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/plugin_modules/mumps)
if(PARASOL_MUMPS_MPI)
  find_package(MPI COMPONENTS Fortran)
  find_library(PARASOL_DMUMPS_LIBRARY NAMES dmumps)
  if(NOT MPI_Fortran_FOUND OR NOT PARASOL_DMUMPS_LIBRARY)
    message(FATAL_ERROR "PARASOL_MUMPS_MPI needs MPI MUMPS and OpenMPI: apt-get install "
                        "libmumps-dev libopenmpi-dev openmpi-bin")
  endif()
  target_include_directories(parasol_mumps PRIVATE ${PARASOL_MUMPS_INCLUDE_DIR})
  target_link_libraries(parasol_mumps PRIVATE ${PARASOL_DMUMPS_LIBRARY} MPI::MPI_Fortran)
  message(STATUS "parasol: MUMPS plug-in with MPI (${PARASOL_DMUMPS_LIBRARY})")
else()
  find_path(PARASOL_MUMPS_SEQ_INCLUDE_DIR mpif.h PATH_SUFFIXES mumps_seq NO_DEFAULT_PATH
            PATHS /usr/include /usr/local/include)
  find_library(PARASOL_DMUMPS_SEQ_LIBRARY NAMES dmumps_seq)
  if(NOT PARASOL_MUMPS_SEQ_INCLUDE_DIR OR NOT PARASOL_DMUMPS_SEQ_LIBRARY)
    message(FATAL_ERROR "parasol's MUMPS back-end needs the sequential MUMPS: apt-get "
                        "install libmumps-seq-dev")
  endif()
  # the sequential library's own mpif.h (MPI stubs) must win over any MPI's
  target_include_directories(parasol_mumps BEFORE PRIVATE ${PARASOL_MUMPS_SEQ_INCLUDE_DIR}
                             ${PARASOL_MUMPS_INCLUDE_DIR})
  target_link_libraries(parasol_mumps PRIVATE ${PARASOL_DMUMPS_SEQ_LIBRARY})
  message(STATUS "parasol: MUMPS plug-in, sequential (${PARASOL_DMUMPS_SEQ_LIBRARY})")
endif()
# mpif.h has no interfaces: MPI_Bcast of integers and reals is legal legacy Fortran
target_compile_options(parasol_mumps PRIVATE -ffree-line-length-none -fallow-argument-mismatch)

foreach(plugin parasol_cholmod parasol_mumps)
  set_target_properties(${plugin} PROPERTIES PREFIX lib
    LIBRARY_OUTPUT_DIRECTORY ${PARASOL_BUILD_PLUGIN_DIR})
endforeach()
install(TARGETS parasol_cholmod parasol_mumps LIBRARY DESTINATION ${PARASOL_INSTALL_PLUGINDIR})

# The flavour, for the program (src/solvers/mumps_solver.f90: MPI workers under mpirun).
if(PARASOL_MUMPS_MPI)
  set(PARASOL_MUMPS_MPI_FORTRAN .true.)
else()
  set(PARASOL_MUMPS_MPI_FORTRAN .false.)
endif()
# The BLAS the skyline loads at run time (src/solvers/blas_library.f90): the real file of the
# library found by ParasolDependencies.cmake.
list(GET PARASOL_LAPACK_LIBRARIES 0 _parasol_blas)
file(REAL_PATH ${_parasol_blas} PARASOL_BLAS_RUNTIME)
configure_file(${PROJECT_SOURCE_DIR}/cmake/parasol_solver_config.f90.in
  ${CMAKE_CURRENT_BINARY_DIR}/generated/parasol_solver_config.f90 @ONLY)
target_sources(parasol_lib PRIVATE
  ${CMAKE_CURRENT_BINARY_DIR}/generated/parasol_solver_config.f90)
