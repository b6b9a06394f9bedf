# expect_said_once.cmake — runs an executable and checks that it succeeds and that exactly one
# line of its stderr matches LINE_REGEX (a condition is said once, not per pass or per thread).
#
#   cmake -DEXECUTABLE=<vkpt-ref> -DARGS="--spp|1|...|scene.gltf" -DLINE_REGEX=<regex>
#         -P expect_said_once.cmake
# ARGS separates arguments with '|'.
foreach(variable EXECUTABLE ARGS LINE_REGEX)
    if(NOT DEFINED ${variable})
        message(FATAL_ERROR "expect_said_once.cmake: -D${variable}=... is missing")
    endif()
endforeach()

string(REPLACE "|" ";" arguments "${ARGS}")
execute_process(
    COMMAND "${EXECUTABLE}" ${arguments}
    RESULT_VARIABLE result
    OUTPUT_VARIABLE stdout
    ERROR_VARIABLE stderr
    TIMEOUT 120)
set(report "\ncommand: ${EXECUTABLE} ${arguments}\nexit: ${result}\nstderr: [${stderr}]")

if(NOT result EQUAL 0)
    message(FATAL_ERROR "expected exit code 0${report}")
endif()
string(REPLACE "\n" ";" lines "${stderr}")
set(matches 0)
foreach(line IN LISTS lines)
    if(line MATCHES "${LINE_REGEX}")
        math(EXPR matches "${matches} + 1")
    endif()
endforeach()
if(NOT matches EQUAL 1)
    message(FATAL_ERROR "expected one stderr line matching '${LINE_REGEX}', found ${matches}${report}")
endif()
