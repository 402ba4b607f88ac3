# The MED plug-in (plugins/med, opened with dlopen by src/mesh/med_file.f90 the first time a
# deck reads or writes MED): libparasol_med.so, the only code linked against Debian's MED
# library (libmedc-dev; it pulls HDF5 and OpenMPI, ~47 libraries, ~10 ms per process start).
# med_abi_check.c checks at build time the med.h constants and type sizes that the Fortran
# bindings of parasol_med_plugin.f90 assume. Built into <build>/lib/parasol, installed into
# <prefix>/lib/parasol; parasol itself never links it.
# Needs PARASOL_BUILD_PLUGIN_DIR and PARASOL_INSTALL_PLUGINDIR (CMakeLists.txt).
find_package(MED REQUIRED)
add_library(parasol_med MODULE ${PROJECT_SOURCE_DIR}/plugins/med/parasol_med_plugin.f90
            ${PROJECT_SOURCE_DIR}/plugins/med/med_abi_check.c)
set_target_properties(parasol_med PROPERTIES PREFIX lib
  LIBRARY_OUTPUT_DIRECTORY ${PARASOL_BUILD_PLUGIN_DIR}
  Fortran_MODULE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/plugin_modules/med)
target_compile_options(parasol_med PRIVATE
  $<$<COMPILE_LANGUAGE:Fortran>:${PARASOL_WARNING_FLAGS}>
  $<$<CONFIG:Debug>:-Werror>)
target_link_libraries(parasol_med PRIVATE MED::MED)
install(TARGETS parasol_med LIBRARY DESTINATION ${PARASOL_INSTALL_PLUGINDIR})
