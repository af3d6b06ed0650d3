# Runs one ggstudio-cli invocation and checks its exit code and output.
# -D CLI=path  -D ARGS="a|b|c" (words separated by |)  -D EXIT=n  [-D OUT=regex] [-D ERR=regex] [-D NOT_OUT=regex]
# [-D WORKDIR=dir] [-D THEN_ARGS="..." -D THEN_EXIT=n -D THEN_OUT=regex]: a second invocation.
# [-D FILE=path -D FILE_CONTENT=regex]: a file the invocations wrote (relative to WORKDIR).
function(run_and_check args expected_exit out_regex err_regex not_out_regex)
    execute_process(COMMAND "${CLI}" ${args}
        WORKING_DIRECTORY "${WORKDIR}"
        RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT code EQUAL expected_exit)
        message(FATAL_ERROR "ggstudio-cli ${args}: exit ${code}, expected ${expected_exit}\nstdout:\n${out}\nstderr:\n${err}")
    endif()
    if(out_regex AND NOT out MATCHES "${out_regex}")
        message(FATAL_ERROR "ggstudio-cli ${args}: stdout does not match '${out_regex}':\n${out}")
    endif()
    if(err_regex AND NOT err MATCHES "${err_regex}")
        message(FATAL_ERROR "ggstudio-cli ${args}: stderr does not match '${err_regex}':\n${err}")
    endif()
    if(not_out_regex AND out MATCHES "${not_out_regex}")
        message(FATAL_ERROR "ggstudio-cli ${args}: stdout matches '${not_out_regex}' but must not:\n${out}")
    endif()
endfunction()

if(NOT WORKDIR)
    set(WORKDIR "${CMAKE_CURRENT_BINARY_DIR}")
endif()
file(MAKE_DIRECTORY "${WORKDIR}")
string(REPLACE "|" ";" ARGS "${ARGS}")
run_and_check("${ARGS}" "${EXIT}" "${OUT}" "${ERR}" "${NOT_OUT}")
if(DEFINED THEN_ARGS)
    string(REPLACE "|" ";" THEN_ARGS "${THEN_ARGS}")
    run_and_check("${THEN_ARGS}" "${THEN_EXIT}" "${THEN_OUT}" "${THEN_ERR}" "${THEN_NOT_OUT}")
endif()
if(DEFINED FILE)
    file(READ "${WORKDIR}/${FILE}" content)
    if(NOT content MATCHES "${FILE_CONTENT}")
        message(FATAL_ERROR "${FILE} does not match '${FILE_CONTENT}':\n${content}")
    endif()
endif()
