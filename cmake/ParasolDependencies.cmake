# Finds parasol's Debian-packaged dependencies; a missing one stops configuration with the
# name of the package to install.

# LAPACK/BLAS: prefer OpenBLAS (libopenblas-dev) when installed, else reference LAPACK.
find_library(PARASOL_OPENBLAS NAMES openblas PATHS /usr/lib/x86_64-linux-gnu/openblas-pthread)
if(PARASOL_OPENBLAS)
  set(PARASOL_LAPACK_LIBRARIES ${PARASOL_OPENBLAS})
  # Debian's OpenBLAS ships LAPACK inside libopenblas; check DPBTRF is really there.
  include(CheckFortranFunctionExists)
  set(CMAKE_REQUIRED_LIBRARIES ${PARASOL_OPENBLAS})
  check_fortran_function_exists(dpbtrf PARASOL_OPENBLAS_HAS_LAPACK)
  unset(CMAKE_REQUIRED_LIBRARIES)
  if(NOT PARASOL_OPENBLAS_HAS_LAPACK)
    find_package(LAPACK REQUIRED)
    set(PARASOL_LAPACK_LIBRARIES ${PARASOL_OPENBLAS} ${LAPACK_LIBRARIES})
  endif()
  message(STATUS "parasol: BLAS/LAPACK from OpenBLAS (${PARASOL_OPENBLAS})")
else()
  find_package(LAPACK QUIET)
  if(NOT LAPACK_FOUND)
    message(FATAL_ERROR "parasol needs LAPACK and BLAS: apt-get install liblapack-dev libblas-dev "
                        "(or libopenblas-dev)")
  endif()
  set(PARASOL_LAPACK_LIBRARIES ${LAPACK_LIBRARIES})
  message(STATUS "parasol: BLAS/LAPACK from reference LAPACK (${LAPACK_LIBRARIES})")
endif()

find_package(METIS REQUIRED)

# Python 3 runs the project's own pFUnit preprocessor and the CLI test scripts.
# Debian's own interpreter, where numpy/meshio/matplotlib from apt live.
if(EXISTS /usr/bin/python3 AND NOT Python3_EXECUTABLE)
  set(Python3_EXECUTABLE /usr/bin/python3)
endif()
find_package(Python3 REQUIRED COMPONENTS Interpreter)
