# `ggstudio-cli verify PACKML_MODEL --promela OUT.pml`, then SPIN on OUT.pml:
# the file must be a Promela model whose exhaustive search completes without
# errors; SPIN must agree with the verify output on the (mode, state) pairs
# never reached (GV134: their `M S reached` marker line is listed as
# unreached) and on GV132 (no `GV132: ...` marker reached when verify reports
# none); and it must reach `REACHED` (a marker comment, "Production Held reached").
# -D CLI=path -D MODEL=file -D REACHED=text -D WORKDIR=dir
find_program(SPIN spin)
find_program(CC gcc)
if(NOT SPIN OR NOT CC)
    message(FATAL_ERROR "spin and gcc are needed (Debian packages spin and gcc)")
endif()
set(dir "${WORKDIR}/spin-packml")
file(REMOVE_RECURSE "${dir}")
file(MAKE_DIRECTORY "${dir}")

execute_process(COMMAND "${CLI}" verify "${MODEL}" --promela "${dir}/model.pml"
    RESULT_VARIABLE code OUTPUT_VARIABLE verify ERROR_VARIABLE err)
if(NOT (code EQUAL 0 OR code EQUAL 1) OR NOT EXISTS "${dir}/model.pml")
    message(FATAL_ERROR "ggstudio-cli verify --promela: exit ${code}\n${verify}\n${err}")
endif()
execute_process(COMMAND "${SPIN}" -o3 -a model.pml WORKING_DIRECTORY "${dir}"
    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "spin -a: exit ${code}\n${out}\n${err}")
endif()
execute_process(COMMAND "${CC}" -O0 -DSAFETY -DMEMLIM=512 -o pan pan.c WORKING_DIRECTORY "${dir}"
    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "compiling pan.c: exit ${code}\n${out}\n${err}")
endif()
execute_process(COMMAND ./pan -m200000 -w20 WORKING_DIRECTORY "${dir}"
    RESULT_VARIABLE code OUTPUT_VARIABLE pan ERROR_VARIABLE err)
if(NOT pan MATCHES "errors: 0\n" OR NOT pan MATCHES "unreached in proctype scan\n"
   OR pan MATCHES "max search depth too small")
    message(FATAL_ERROR "pan did not complete its search:\n${pan}\n${err}")
endif()

string(REGEX MATCHALL "model\\.pml:[0-9]+," listed "${pan}")
set(unreached "")
foreach(item IN LISTS listed)
    string(REGEX REPLACE "model\\.pml:([0-9]+)," "\\1" line "${item}")
    list(APPEND unreached ${line})
endforeach()

# One list element a line: the semicolons of Promela would split lines.
file(READ "${dir}/model.pml" content)
string(REPLACE ";" "," content "${content}")
string(REPLACE "\n" ";" lines "${content}")
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
