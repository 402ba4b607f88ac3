# Runs a deck with another SOLVEUR/METHODE: the deck's SOLVEUR=_F(...) is replaced by
# SOLVEUR=_F(METHODE='<METHOD>', NPREC=<NPREC>) in a copy (same file name, in OUTDIR/deck),
# then tests/analysis/run_deck.cmake runs and checks it with the other arguments.
#
# (EXTRA: more keywords of SOLVEUR, "RESI_RELA=1e-10").
#   cmake -DMETHOD=MUMPS -DNPREC=9 [-DEXTRA=...] -DPARASOL=exe -DDECK=x.comm -DOUTDIR=dir [-DMESH=...]
#         [-DREF=... -DDIFF=... -DRTOL=...] [-DLAUNCHER=mpiexec|-np|2]
#         -DRUNNER=run_deck.cmake -P with_method.cmake
get_filename_component(name ${DECK} NAME)
file(READ ${DECK} text)
string(REGEX MATCH "SOLVEUR=_F\\([^)]*\\)" found "${text}")
if(NOT found)
    message(FATAL_ERROR "${DECK} has no SOLVEUR=_F(...) to replace")
endif()
set(extra "")
if(DEFINED EXTRA)
    set(extra ", ${EXTRA}")
endif()
string(REPLACE "${found}" "SOLVEUR=_F(METHODE='${METHOD}', NPREC=${NPREC}${extra})" text "${text}")
file(MAKE_DIRECTORY ${OUTDIR}/deck)
file(WRITE ${OUTDIR}/deck/${name} "${text}")
set(args -DPARASOL=${PARASOL} -DDECK=${OUTDIR}/deck/${name} -DOUTDIR=${OUTDIR}/run)
foreach(var MESH REF DIFF RTOL LAUNCHER MESS_REGEX)
    if(DEFINED ${var})
        list(APPEND args -D${var}=${${var}})
    endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} ${args} -P ${RUNNER} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name} with METHODE='${METHOD}' failed")
endif()
