# Installs the build into a fresh prefix and runs the installed parasol with no deck from an
# unrelated folder: it must find its bundled deck and mesh in <prefix>/share/parasol and
# exit 0 with every TEST_RESU OK (issue: "an installable program").
#   cmake -DBUILD_DIR=dir -DWORK=dir -P install_and_run.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/elsewhere)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK}/prefix
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cmake --install failed (${rc}):\n${out}${err}")
endif()
foreach(f bin/parasol bin/parasol-diff bin/parasol-bench share/parasol/ssnl130a.comm
          share/parasol/ssnl130a.mail share/doc/parasol/README.md)
    if(NOT EXISTS ${WORK}/prefix/${f})
        message(FATAL_ERROR "the install lacks ${f}")
    endif()
endforeach()
execute_process(COMMAND ${WORK}/prefix/bin/parasol WORKING_DIRECTORY ${WORK}/elsewhere
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the installed parasol exited with ${rc}")
endif()
if(NOT out MATCHES "share/parasol/ssnl130a.comm" OR
   NOT out MATCHES "parasol: every TEST_RESU check is OK")
    message(FATAL_ERROR "the installed parasol did not run its bundled deck from share/parasol")
endif()
if(NOT EXISTS ${WORK}/elsewhere/ssnl130a.resu)
    message(FATAL_ERROR "no listing written in the current folder")
endif()
