# expect_frames.cmake — renders frames 0 to 2 of an animated scene and checks the numbered images
# and statistics; run again, every frame must be skipped, and nothing rewritten.
#
#   cmake -DEXECUTABLE=<vkpt-ref> -DSCENE=<file> -DDIRECTORY=<scratch folder> -P expect_frames.cmake
foreach(variable EXECUTABLE SCENE DIRECTORY)
    if(NOT DEFINED ${variable})
        message(FATAL_ERROR "expect_frames.cmake: -D${variable}=... is missing")
    endif()
endforeach()

file(REMOVE_RECURSE "${DIRECTORY}")
file(MAKE_DIRECTORY "${DIRECTORY}")
set(command "${EXECUTABLE}" --spp 1 --res 8 8 --quiet --frames 0:2 --fps 2
    --output "${DIRECTORY}/frame.###.png" --stats-json "${DIRECTORY}/stats.###.json" "${SCENE}")

execute_process(COMMAND ${command} RESULT_VARIABLE result ERROR_VARIABLE stderr TIMEOUT 100)
set(report "\ncommand: ${command}\nexit: ${result}\nstderr: [${stderr}]")
if(NOT result STREQUAL "0")
    message(FATAL_ERROR "expected exit code 0${report}")
endif()
foreach(frame 000 001 002)
    foreach(file "frame.${frame}.png" "stats.${frame}.json")
        if(NOT EXISTS "${DIRECTORY}/${file}")
            message(FATAL_ERROR "expected ${file} to be written${report}")
        endif()
    endforeach()
endforeach()
if(NOT stderr MATCHES "frame 1 at 0.5 s")
    message(FATAL_ERROR "expected frame 1 posed at 0.5 s (--fps 2)${report}")
endif()
file(TIMESTAMP "${DIRECTORY}/frame.001.png" before "%s")

execute_process(COMMAND ${command} RESULT_VARIABLE result ERROR_VARIABLE stderr TIMEOUT 100)
set(report "\ncommand: ${command}\nexit: ${result}\nstderr: [${stderr}]")
string(REGEX MATCHALL "png exists" skipped "${stderr}")
list(LENGTH skipped skippedCount)
if(NOT result STREQUAL "0" OR NOT skippedCount EQUAL 3)
    message(FATAL_ERROR "expected the second run to skip all 3 frames${report}")
endif()
file(TIMESTAMP "${DIRECTORY}/frame.001.png" after "%s")
if(NOT before STREQUAL after)
    message(FATAL_ERROR "frame.001.png was written again${report}")
endif()
