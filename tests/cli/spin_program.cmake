# `ggstudio-cli verify MODEL --property P --promela OUT.pml` on a model with
# nested GRAFCETs, then SPIN on OUT.pml: the file is the program of both
# layers (core/verification/promelaprogram.h), pan's exhaustive search
# completes, and the marker line of the property is reached (not listed as
# unreached) iff verify reports it violated (GV120, exit 1).
# -D CLI=path -D MODEL=file -D PROPERTY=text -D WORKDIR=dir
find_program(SPIN spin)
find_program(CC gcc)
if(NOT SPIN OR NOT CC)
    message(FATAL_ERROR "spin and gcc are needed (Debian packages spin and gcc)")
endif()
set(dir "${WORKDIR}/spin-program")
file(REMOVE_RECURSE "${dir}")
file(MAKE_DIRECTORY "${dir}")
# -D MACHINE=ON: closed loop (verify --machine), the machine in the Promela file too.
# The verdict SPIN is compared with must be decided, and a sanitizer build on a
# loaded CI machine may need more than the default 4 s: the closed loop's search
# counted in scans (the run stops as soon as it is done), or the 38,522 states
# with single faults on the drilling cell (decided in the first exploration,
# under 1 s there; a search for the runs of other findings then goes on to the
# limit, which is all 8 s bounds).
set(closedLoop "")
if(MACHINE)
    set(closedLoop --machine --time-limit 60s)
endif()
# -D FAULTS=ON: with single faults (verify --machine --faults single), in the Promela file too.
if(FAULTS)
    set(closedLoop --machine --faults single --time-limit 8s)
endif()
execute_process(COMMAND "${CLI}" verify "${MODEL}" --property "${PROPERTY}" --promela "${dir}/model.pml" ${closedLoop}
    RESULT_VARIABLE verifyCode OUTPUT_VARIABLE verify ERROR_VARIABLE err)
if(NOT (verifyCode EQUAL 0 OR verifyCode EQUAL 1) OR NOT EXISTS "${dir}/model.pml")
    message(FATAL_ERROR "ggstudio-cli verify --promela: exit ${verifyCode}\n${verify}\n${err}")
endif()
file(READ "${dir}/model.pml" text)
if(NOT text MATCHES "Both layers of")
    message(FATAL_ERROR "--promela did not write both layers:\n${text}")
endif()
if(MACHINE AND NOT text MATCHES "the machine's cycle")
    message(FATAL_ERROR "--promela --machine did not write the machine:\n${text}")
endif()
if(FAULTS AND NOT text MATCHES "single faults")
    message(FATAL_ERROR "--promela --faults single did not write the faults:\n${text}")
endif()
execute_process(COMMAND "${SPIN}" -o3 -a model.pml WORKING_DIRECTORY "${dir}" RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "spin -a: exit ${code}\n${err}")
endif()
execute_process(COMMAND "${CC}" -O0 -DSAFETY -DMEMLIM=512 -o pan pan.c WORKING_DIRECTORY "${dir}"
    RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "compiling pan.c: exit ${code}\n${err}")
endif()
execute_process(COMMAND ./pan -m200000 -w20 WORKING_DIRECTORY "${dir}" OUTPUT_VARIABLE pan)
if(NOT pan MATCHES "errors: 0\n" OR NOT pan MATCHES "unreached in proctype scan\n")
    message(FATAL_ERROR "pan did not complete its search:\n${pan}")
endif()
# The property given on the command line is the last one: its marker line.
string(REGEX MATCHALL "[^\n]*violated \\*/" markers "${text}")
list(LENGTH markers count)
if(count EQUAL 0)
    message(FATAL_ERROR "no property marker in the Promela file")
endif()
file(STRINGS "${dir}/model.pml" lines)
set(number 0)
set(markerLine 0)
foreach(line IN LISTS lines)
    math(EXPR number "${number} + 1")
    if(line MATCHES "property [0-9]+ violated \\*/")
        set(markerLine ${number})
    endif()
endforeach()
if(pan MATCHES "model\\.pml:${markerLine},")
    set(spinViolated FALSE)
else()
    set(spinViolated TRUE)
endif()
if(verify MATCHES "GV120")
    set(verifyViolated TRUE)
else()
    set(verifyViolated FALSE)
endif()
if(NOT spinViolated STREQUAL verifyViolated)
    message(FATAL_ERROR "SPIN says violated=${spinViolated} (line ${markerLine}), verify says ${verifyViolated}:\n${verify}")
endif()
message(STATUS "SPIN and verify agree: '${PROPERTY}' violated=${spinViolated}")
