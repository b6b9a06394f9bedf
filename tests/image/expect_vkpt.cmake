# expect_vkpt.cmake — runs vkpt with ARGS and checks the command-line contract: the exit code,
# and that stderr ends with one line matching STDERR_REGEX (and, with STDERR_LINES, has exactly
# that many lines), and that stdout matches STDOUT_REGEX.
#
#   cmake -DEXECUTABLE=<vkpt> -DARGS="--device|no-such-device|..." -DEXPECTED_EXIT=2
#         [-DSTDERR_REGEX=<regex>] [-DSTDERR_LINES=<n>] [-DSTDOUT_REGEX=<regex>]
#         -P expect_vkpt.cmake
# ARGS separates arguments with '|', since CMake lists would split at semicolons of regexes.
foreach(variable EXECUTABLE ARGS EXPECTED_EXIT)
    if(NOT DEFINED ${variable})
        message(FATAL_ERROR "expect_vkpt.cmake: -D${variable}=... is missing")
    endif()
endforeach()

string(REPLACE "|" ";" arguments "${ARGS}")
execute_process(
    COMMAND "${EXECUTABLE}" ${arguments}
    RESULT_VARIABLE result
    OUTPUT_VARIABLE stdout
    ERROR_VARIABLE stderr
    TIMEOUT 120)

set(report "\ncommand: ${EXECUTABLE} ${arguments}\nexit: ${result}\nstderr: [${stderr}]\nstdout: [${stdout}]")

if(NOT result STREQUAL "${EXPECTED_EXIT}")
    message(FATAL_ERROR "expected exit code ${EXPECTED_EXIT}${report}")
endif()

if(DEFINED STDERR_LINES)
    string(REGEX MATCHALL "\n" newlines "${stderr}")
    list(LENGTH newlines lineBreaks)
    if(NOT lineBreaks EQUAL STDERR_LINES OR (STDERR_LINES GREATER 0 AND NOT stderr MATCHES "\n$"))
        message(FATAL_ERROR "expected exactly ${STDERR_LINES} line(s) on stderr${report}")
    endif()
endif()

if(DEFINED STDERR_REGEX)
    string(REGEX REPLACE "\n$" "" trimmed "${stderr}")
    string(REGEX REPLACE "^.*\n" "" lastLine "${trimmed}")
    if(NOT lastLine MATCHES "^(${STDERR_REGEX})$")
        message(FATAL_ERROR "expected the last stderr line to match '${STDERR_REGEX}'${report}")
    endif()
endif()

if(DEFINED STDOUT_REGEX AND NOT stdout MATCHES "${STDOUT_REGEX}")
    message(FATAL_ERROR "expected stdout to match '${STDOUT_REGEX}'${report}")
endif()
