# Unit suites (tests/unit/*.pf), both paths of doc/testing.md:
#  1. real pFUnit 4 when find_package(PFUNIT 4) finds it (e.g. CMAKE_PREFIX_PATH=<prefix>);
#  2. otherwise parasol's own preprocessor (tests/pfunit/pfunit_preprocess.py) and assertion
#     module (tests/pfunit/funit.f90), one CTest test per suite.
find_package(PFUNIT 4 QUIET)
if(PFUNIT_FOUND)
  message(STATUS "parasol: unit suites use pFUnit ${PFUNIT_VERSION}")
else()
  message(STATUS "parasol: pFUnit 4 not found; unit suites use parasol's own preprocessor "
                 "(tests/pfunit)")
  add_library(parasol_funit STATIC ${PROJECT_SOURCE_DIR}/tests/pfunit/funit.f90)
  set_target_properties(parasol_funit PROPERTIES
    Fortran_MODULE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/funit_modules)
  target_include_directories(parasol_funit PUBLIC ${CMAKE_CURRENT_BINARY_DIR}/funit_modules)
endif()

# parasol_add_unit_suite(<file.pf>) registers the suite as the CTest test unit.<stem>.
function(parasol_add_unit_suite pf_file)
  get_filename_component(stem ${pf_file} NAME_WE)
  if(PFUNIT_FOUND)
    # add_pfunit_ctest writes the generated .F90 beside an absolute TEST_SOURCES path (it
    # takes it for a build-tree file), so the suite is named relative to this folder: the
    # generated source then goes to the build tree. The test gets the same name as on the
    # fallback path (unit.<stem>), and the same line-length option (pfunit.md).
    file(RELATIVE_PATH pf_relative ${CMAKE_CURRENT_SOURCE_DIR} ${pf_file})
    add_pfunit_ctest(unit.${stem} TEST_SOURCES ${pf_relative} LINK_LIBRARIES parasol_lib
                     ${PARASOL_LAPACK_LIBRARIES})
    target_compile_options(unit.${stem} PRIVATE -ffree-line-length-none)
    set_tests_properties(unit.${stem} PROPERTIES LABELS unit
      ENVIRONMENT PARASOL_SOURCE_DIR=${PROJECT_SOURCE_DIR})
    return()
  endif()
  set(gen ${CMAKE_CURRENT_BINARY_DIR}/pfunit_generated)
  add_custom_command(
    OUTPUT ${gen}/${stem}.F90 ${gen}/${stem}_driver.f90
    COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tests/pfunit/pfunit_preprocess.py
            ${pf_file} ${gen}
    DEPENDS ${pf_file} ${PROJECT_SOURCE_DIR}/tests/pfunit/pfunit_preprocess.py
    COMMENT "pFUnit subset: ${stem}.pf")
  add_executable(${stem} ${gen}/${stem}.F90 ${gen}/${stem}_driver.f90)
  set_target_properties(${stem} PROPERTIES
    Fortran_MODULE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/suite_modules/${stem})
  target_compile_options(${stem} PRIVATE -ffree-line-length-none)
  target_link_libraries(${stem} PRIVATE parasol_lib parasol_funit ${PARASOL_LAPACK_LIBRARIES})
  add_test(NAME unit.${stem} COMMAND ${stem})
  # Suites that read committed data (meshes, decks) find the source tree through this.
  set_tests_properties(unit.${stem} PROPERTIES LABELS unit
    ENVIRONMENT PARASOL_SOURCE_DIR=${PROJECT_SOURCE_DIR})
endfunction()
