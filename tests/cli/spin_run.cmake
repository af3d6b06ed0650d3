# run_spin(DIR): spin -o3 -a, gcc and pan on DIR/model.pml, as kSpinGenerate
# and the tests' compile flags do; fails unless pan's search completes.
# Sets `pan` (its output) and `unreached` (the line numbers it lists as
# unreached in proctype scan) in the caller's scope.
find_program(SPIN spin)
find_program(CC gcc)
if(NOT SPIN OR NOT CC)
    message(FATAL_ERROR "spin and gcc are needed (Debian packages spin and gcc)")
endif()

# export_promela(DIR): `ggstudio-cli verify MODEL --promela DIR/model.pml`,
# which must write the file and exit 0 or 1 (findings); sets `verify` (its
# output) in the caller's scope.
function(export_promela dir)
    execute_process(COMMAND "${CLI}" verify "${MODEL}" --promela "${dir}/model.pml"
        RESULT_VARIABLE code OUTPUT_VARIABLE output ERROR_VARIABLE err)
    if(NOT (code EQUAL 0 OR code EQUAL 1) OR NOT EXISTS "${dir}/model.pml")
        message(FATAL_ERROR "ggstudio-cli verify --promela: exit ${code}\n${output}\n${err}")
    endif()
    set(verify "${output}" PARENT_SCOPE)
endfunction()

function(run_spin dir)
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
        RESULT_VARIABLE code OUTPUT_VARIABLE output ERROR_VARIABLE err)
    if(NOT output MATCHES "errors: 0\n" OR NOT output MATCHES "unreached in proctype scan\n"
       OR output MATCHES "max search depth too small")
        message(FATAL_ERROR "pan did not complete its search:\n${output}\n${err}")
    endif()
    string(REGEX MATCHALL "model\\.pml:[0-9]+," listed "${output}")
    set(lines "")
    foreach(item IN LISTS listed)
        string(REGEX REPLACE "model\\.pml:([0-9]+)," "\\1" line "${item}")
        list(APPEND lines ${line})
    endforeach()
    set(pan "${output}" PARENT_SCOPE)
    set(unreached "${lines}" PARENT_SCOPE)
endfunction()

# model_lines(DIR): sets `lines` to DIR/model.pml, one list element a line,
# so that element k is line k as pan numbers them. file(STRINGS) would drop
# empty lines and let Promela's semicolons split a line in two; brackets are
# replaced too, as CMake does not split a list inside them.
function(model_lines dir)
    file(READ "${dir}/model.pml" content)
    string(REPLACE ";" "," content "${content}")
    string(REPLACE "[" "(" content "${content}")
    string(REPLACE "]" ")" content "${content}")
    string(REPLACE "\n" ";" content "${content}")
    set(lines "${content}" PARENT_SCOPE)
endfunction()
