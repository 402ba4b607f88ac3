# Runs one deck and checks what it produced (cmake -P, so the tests need no Python).
#
#   cmake -DPARASOL=exe -DDECK=x.comm -DOUTDIR=dir [-DMESH=x.mail] [-DEXPECT_EXIT=0]
#         [-DREF=x.resu.ref -DDIFF=parasol-diff -DRTOL=r]       # compare the .resu
#         [-DREPEAT=1]                                          # run twice, byte-identical
#         [-DMESS_REGEX=re] [-DOUT_REGEX=re]                    # .mess / stdout+stderr match
#         [-DCOMPARE_DECK=y.comm -DMESS_LINE_REGEX=re]          # same matching .mess parts
#         [-DNO_DECK=1]                                         # run parasol without a deck
#         [-DLAUNCHER=mpiexec|-np|2]                            # run parasol under it
#         -P run_deck.cmake
#
# The test fails (message(FATAL_ERROR)) when the exit status is not EXPECT_EXIT, when the
# .resu differs from REF beyond RTOL (parasol-diff), when two runs differ by a byte, when a
# regular expression is not found, or when the parts of the .mess matching MESS_LINE_REGEX
# differ from those of COMPARE_DECK's .mess (run first, must exit 0), e.g. the
# "N of M springs closed" of every step of two decks.
if(NOT DEFINED EXPECT_EXIT)
    set(EXPECT_EXIT 0)
endif()
get_filename_component(stem ${DECK} NAME_WE)
file(MAKE_DIRECTORY ${OUTDIR})

function(run_once outdir)
    file(MAKE_DIRECTORY ${outdir})
    set(cmd ${PARASOL} --outdir ${outdir})
    if(DEFINED LAUNCHER)
        string(REPLACE "|" ";" launcher "${LAUNCHER}")
        set(cmd ${launcher} ${cmd})
    endif()
    if(DEFINED MESH)
        list(APPEND cmd --unit 20=${MESH})
    endif()
    if(NOT NO_DECK)
        list(APPEND cmd ${DECK})
    endif()
    execute_process(COMMAND ${cmd} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    message("${out}${err}")
    if(NOT "${rc}" STREQUAL "${EXPECT_EXIT}")
        message(FATAL_ERROR "parasol exited with ${rc}, expected ${EXPECT_EXIT}")
    endif()
    if(DEFINED OUT_REGEX AND NOT "${out}${err}" MATCHES "${OUT_REGEX}")
        message(FATAL_ERROR "the terminal output does not match \"${OUT_REGEX}\"")
    endif()
endfunction()

run_once(${OUTDIR})
set(resu ${OUTDIR}/${stem}.resu)
set(mess ${OUTDIR}/${stem}.mess)

if(DEFINED MESS_REGEX)
    file(READ ${mess} text)
    if(NOT text MATCHES "${MESS_REGEX}")
        message(FATAL_ERROR "${mess} does not match \"${MESS_REGEX}\"")
    endif()
endif()

if(DEFINED COMPARE_DECK)
    get_filename_component(other ${COMPARE_DECK} NAME_WE)
    file(MAKE_DIRECTORY ${OUTDIR}/compare)
    execute_process(COMMAND ${PARASOL} --outdir ${OUTDIR}/compare ${COMPARE_DECK}
                    RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
    if(NOT rc EQUAL 0)
        message(FATAL_ERROR "the deck compared with, ${COMPARE_DECK}, exited with ${rc}")
    endif()
    file(READ ${mess} text)
    string(REGEX MATCHALL "${MESS_LINE_REGEX}" mine "${text}")
    file(READ ${OUTDIR}/compare/${other}.mess text)
    string(REGEX MATCHALL "${MESS_LINE_REGEX}" theirs "${text}")
    message("${stem}: ${mine}\n${other}: ${theirs}")
    if(NOT mine)
        message(FATAL_ERROR "nothing in ${mess} matches \"${MESS_LINE_REGEX}\"")
    endif()
    if(NOT "${mine}" STREQUAL "${theirs}")
        message(FATAL_ERROR "the .mess of ${stem} and ${other} differ in \"${MESS_LINE_REGEX}\"")
    endif()
endif()

if(DEFINED REF)
    # The ERREUR column of a TEST_RESU check line is derived from the two values beside it
    # (compared here); it is a difference of nearly equal numbers, so its own relative change
    # between builds is large and meaningless. It is left out of both files; TOLE stays.
    foreach(pair "${resu};${OUTDIR}/${stem}.resu.cmp" "${REF};${OUTDIR}/${stem}.resu.ref.cmp")
        list(GET pair 0 from)
        list(GET pair 1 to)
        file(STRINGS ${from} lines)
        set(text "")
        foreach(line IN LISTS lines)
            if(line MATCHES "^( OK   |NOOK  )")
                string(REGEX REPLACE "[^ ]+%( +[^ ]+%)$" "\\1" line "${line}")
            endif()
            string(APPEND text "${line}\n")
        endforeach()
        file(WRITE ${to} "${text}")
    endforeach()
    execute_process(COMMAND ${DIFF} ${OUTDIR}/${stem}.resu.cmp ${OUTDIR}/${stem}.resu.ref.cmp
                            --rtol ${RTOL} RESULT_VARIABLE rc
                    OUTPUT_VARIABLE out ERROR_VARIABLE err)
    message("${out}${err}")
    if(NOT rc EQUAL 0)
        message(FATAL_ERROR "${resu} differs from ${REF} beyond rtol ${RTOL} "
                            "(ERREUR columns left out)")
    endif()
endif()

if(REPEAT)
    run_once(${OUTDIR}/again)
    foreach(ext resu)
        execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files
                                ${OUTDIR}/${stem}.${ext} ${OUTDIR}/again/${stem}.${ext}
                        RESULT_VARIABLE rc)
        if(NOT rc EQUAL 0)
            message(FATAL_ERROR "two runs gave different ${stem}.${ext}")
        endif()
    endforeach()
endif()
