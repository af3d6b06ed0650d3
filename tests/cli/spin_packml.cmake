# `ggstudio-cli verify PACKML_MODEL --promela OUT.pml`, then SPIN on OUT.pml:
# the file must be a Promela model whose exhaustive search completes without
# errors; SPIN must agree with the verify output on the (mode, state) pairs
# never reached (GV134: their `M S reached` marker line is listed as
# unreached) and on GV132 (no `GV132: ...` marker reached when verify reports
# none); and it must reach `REACHED` (a marker comment, "Production Held reached").
# -D CLI=path -D MODEL=file -D REACHED=text -D WORKDIR=dir
include("${CMAKE_CURRENT_LIST_DIR}/spin_run.cmake")
set(dir "${WORKDIR}/spin-packml")
file(REMOVE_RECURSE "${dir}")
file(MAKE_DIRECTORY "${dir}")

export_promela("${dir}")
run_spin("${dir}")

model_lines("${dir}")
set(number 0)
set(markers 0)
set(expected FALSE)
foreach(text IN LISTS lines)
    math(EXPR number "${number} + 1")
    list(FIND unreached ${number} found)
    if(text MATCHES "/\\* ([A-Za-z0-9_]+) ([A-Za-z]+) reached \\*/")
        math(EXPR markers "${markers} + 1")
        if(verify MATCHES ": ${CMAKE_MATCH_1}: ${CMAKE_MATCH_2}: warning: GV134: " AND found EQUAL -1)
            message(FATAL_ERROR "verify says ${CMAKE_MATCH_1} ${CMAKE_MATCH_2} is never active, SPIN reaches it")
        endif()
    elseif(text MATCHES "/\\* GV132: ")
        if(NOT verify MATCHES "GV132" AND found EQUAL -1)
            message(FATAL_ERROR "SPIN reaches a state a mode disables (line ${number}), verify reports no GV132")
        endif()
    endif()
    if(text MATCHES "/\\* ${REACHED} \\*/")
        set(expected TRUE)
        if(NOT found EQUAL -1)
            message(FATAL_ERROR "SPIN never reaches '${REACHED}'")
        endif()
    endif()
endforeach()
if(markers EQUAL 0 OR NOT expected)
    message(FATAL_ERROR "model.pml has no reach markers, or none for '${REACHED}'")
endif()
