# `ggstudio-cli verify MODEL --promela OUT.pml`, then SPIN on OUT.pml: the file
# must be a Promela model whose exhaustive search completes without errors,
# and SPIN must agree with the verify output on unreachable steps (GV101: the
# `reach S` marker line is listed as unreached iff S is reported) and on stuck
# steps (GV106: the `no fire in S` marker line is reached).
# -D CLI=path -D MODEL=file (or "template": a new model) -D WORKDIR=dir
include("${CMAKE_CURRENT_LIST_DIR}/spin_run.cmake")
set(dir "${WORKDIR}/spin-promela")
file(REMOVE_RECURSE "${dir}")
file(MAKE_DIRECTORY "${dir}")

if(MODEL STREQUAL "template")
    set(MODEL "${dir}/template.json")
    execute_process(COMMAND "${CLI}" new "${MODEL}" RESULT_VARIABLE code)
    if(NOT code EQUAL 0)
        message(FATAL_ERROR "ggstudio-cli new: exit ${code}")
    endif()
endif()
export_promela("${dir}")

run_spin("${dir}")

model_lines("${dir}")
set(number 0)
set(markers 0)
foreach(text IN LISTS lines)
    math(EXPR number "${number} + 1")
    list(FIND unreached ${number} found)
    if(text MATCHES "/\\* reach ([A-F][0-9]) \\*/")
        math(EXPR markers "${markers} + 1")
        set(step ${CMAKE_MATCH_1})
        set(reported FALSE)
        if(verify MATCHES ": ${step}(, [^:\n]*)?: warning: GV101: ")
            set(reported TRUE)
        endif()
        if((found EQUAL -1 AND reported) OR (NOT found EQUAL -1 AND NOT reported))
            message(FATAL_ERROR "SPIN and verify disagree on whether ${step} is reachable:\n${verify}\n${pan}")
        endif()
    elseif(text MATCHES "/\\* no fire in ([A-F][0-9]) \\*/")
        set(step ${CMAKE_MATCH_1})
        if(verify MATCHES ": ${step}(, [^:\n]*)?: error: GV106: " AND NOT found EQUAL -1)
            message(FATAL_ERROR "verify says ${step} is stuck, SPIN finds an input that fires in every situation")
        endif()
    endif()
endforeach()
if(markers EQUAL 0)
    message(FATAL_ERROR "model.pml has no reach markers")
endif()
