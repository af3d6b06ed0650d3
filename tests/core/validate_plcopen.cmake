# Schema validation of the PLCopen XML export (spec §7), run by CTest:
#   cmake -DSAMPLES=<plcopen_samples> -DOUT=<folder> -DXSD=<tc6_xml_v201.xsd> -P validate_plcopen.cmake
# Writes the samples, then validates them all with one xmllint call.

foreach(required SAMPLES OUT XSD)
    if(NOT DEFINED ${required})
        message(FATAL_ERROR "validate_plcopen.cmake: -D${required}=... is missing")
    endif()
endforeach()
if(NOT EXISTS "${XSD}")
    message(FATAL_ERROR "The PLCopen schema is not at ${XSD} (tests/data/plcopen in the repository)")
endif()
find_program(XMLLINT xmllint)
if(NOT XMLLINT)
    message(FATAL_ERROR "xmllint not found: install libxml2-utils")
endif()

file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
execute_process(COMMAND "${SAMPLES}" "${OUT}" RESULT_VARIABLE status)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "plcopen_samples failed (${status})")
endif()

file(GLOB samples "${OUT}/*.xml")
list(LENGTH samples count)
if(count LESS 203)
    message(FATAL_ERROR "expected at least 203 samples in ${OUT}, found ${count}")
endif()

execute_process(COMMAND "${XMLLINT}" --noout --nonet --schema "${XSD}" ${samples}
                RESULT_VARIABLE status ERROR_VARIABLE report)
if(NOT status EQUAL 0)
    # Keep only the complaints, not the "X validates" lines.
    string(REGEX REPLACE "[^\n]* validates\n" "" complaints "${report}")
    message(FATAL_ERROR "PLCopen samples do not validate against ${XSD}:\n${complaints}")
endif()
message(STATUS "${count} PLCopen samples validate against ${XSD}")
