# expect_failure.cmake — runs vkpt-ref on input it must reject, and checks the one-line contract
# of DESIGN.md: exit code exactly 1, exactly one line on stderr, "<program>: error: <scene>: "
# followed by a message matching EXPECTED_MESSAGE (a regex for the whole rest of the line), and
# no image written.
#
#   cmake -DEXECUTABLE=<vkpt-ref> -DSCENE=<file> -DOUTPUT=<image.pfm>
#         -DEXPECTED_MESSAGE=<regex> -P expect_failure.cmake
foreach(variable EXECUTABLE SCENE OUTPUT EXPECTED_MESSAGE)
    if(NOT DEFINED ${variable})
        message(FATAL_ERROR "expect_failure.cmake: -D${variable}=... is missing")
    endif()
endforeach()

file(REMOVE "${OUTPUT}")
execute_process(
    COMMAND "${EXECUTABLE}" --spp 1 --res 8 8 --output "${OUTPUT}" "${SCENE}"
    RESULT_VARIABLE result
    OUTPUT_VARIABLE stdout
    ERROR_VARIABLE stderr
    TIMEOUT 60)

# Everything a failure report needs, since ctest shows only this output.
set(report "\ncommand: ${EXECUTABLE} --spp 1 --res 8 8 --output ${OUTPUT} ${SCENE}\n")
string(APPEND report "exit: ${result}\nstderr: [${stderr}]\nstdout: [${stdout}]")

if(NOT result STREQUAL "1")
    message(FATAL_ERROR "expected exit code 1 (bad input)${report}")
endif()

string(REGEX MATCHALL "\n" newlines "${stderr}")
list(LENGTH newlines lineBreaks)
if(NOT lineBreaks EQUAL 1 OR NOT stderr MATCHES "\n$")
    message(FATAL_ERROR "expected exactly one line on stderr${report}")
endif()

get_filename_component(program "${EXECUTABLE}" NAME)
set(prefix "${program}: error: ${SCENE}: ")
string(FIND "${stderr}" "${prefix}" prefixAt)
if(NOT prefixAt EQUAL 0)
    message(FATAL_ERROR "expected stderr to start with '${prefix}'${report}")
endif()

string(LENGTH "${prefix}" prefixLength)
string(SUBSTRING "${stderr}" ${prefixLength} -1 message)
string(REGEX REPLACE "\n$" "" message "${message}")
if(NOT message MATCHES "^(${EXPECTED_MESSAGE})$")
    message(FATAL_ERROR "expected the message to match '${EXPECTED_MESSAGE}'${report}")
endif()

if(EXISTS "${OUTPUT}")
    message(FATAL_ERROR "an image was written although the input was rejected${report}")
endif()
