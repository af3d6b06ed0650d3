# Runs ggstudio-cli against a target that is not a regular file and checks
# that the command is refused and the target left as it was.
# -D CLI=path -D WORKDIR=dir -D NAME=test name -D KIND=fifo|device-link -D TARGET=relative path
# -D ARGS="a|b|@BASE@/x" (words separated by |; @BASE@ is the test's own fresh folder)
# -D EXIT=n [-D ERR=regex] [-D OUT=regex]
# KIND fifo makes TARGET a FIFO (its folders created first); device-link makes
# it a symbolic link to a character device: a private node with /dev/null's
# numbers where mknod is allowed (as root, who could replace /dev/null
# itself), else /dev/null, which an ordinary user cannot replace.
set(base "${WORKDIR}/${NAME}")
file(REMOVE_RECURSE "${base}")
set(target "${base}/${TARGET}")
get_filename_component(parent "${target}" DIRECTORY)
file(MAKE_DIRECTORY "${parent}")

function(require_success what)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE code ERROR_VARIABLE err)
    if(NOT code EQUAL 0)
        message(FATAL_ERROR "${what}: ${ARGN}: exit ${code}: ${err}")
    endif()
endfunction()

if(KIND STREQUAL "fifo")
    require_success("cannot make the FIFO" mkfifo "${target}")
elseif(KIND STREQUAL "device-link")
    set(device "${base}/null-device")
    execute_process(COMMAND mknod "${device}" c 1 3 RESULT_VARIABLE code OUTPUT_QUIET ERROR_QUIET)
    if(NOT code EQUAL 0)
        set(device "/dev/null")
    endif()
    file(CREATE_LINK "${device}" "${target}" SYMBOLIC)
else()
    message(FATAL_ERROR "KIND must be fifo or device-link, not '${KIND}'")
endif()

string(REPLACE "@BASE@" "${base}" ARGS "${ARGS}")
string(REPLACE "|" ";" ARGS "${ARGS}")
execute_process(COMMAND "${CLI}" ${ARGS} WORKING_DIRECTORY "${base}"
    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL EXIT)
    message(FATAL_ERROR "ggstudio-cli ${ARGS}: exit ${code}, expected ${EXIT}\nstdout:\n${out}\nstderr:\n${err}")
endif()
if(ERR AND NOT err MATCHES "${ERR}")
    message(FATAL_ERROR "ggstudio-cli ${ARGS}: stderr does not match '${ERR}':\n${err}")
endif()
if(OUT AND NOT out MATCHES "${OUT}")
    message(FATAL_ERROR "ggstudio-cli ${ARGS}: stdout does not match '${OUT}':\n${out}")
endif()

if(KIND STREQUAL "fifo")
    execute_process(COMMAND test -p "${target}" RESULT_VARIABLE code)
    if(NOT code EQUAL 0)
        message(FATAL_ERROR "${target} is no longer a FIFO")
    endif()
else()
    execute_process(COMMAND test -c "${device}" RESULT_VARIABLE code)
    if(NOT code EQUAL 0 OR NOT IS_SYMLINK "${target}")
        message(FATAL_ERROR "${device} is no longer a character device, or ${target} no longer a link to it")
    endif()
endif()
