# expect_outputs.cmake — runs a renderer on a valid scene and checks the success contract:
# exit code 0, the image in the requested format, the sample-count heat map beside it and the
# statistics JSON with the figures the summary promises.
#
#   cmake -DEXECUTABLE=<vkpt-ref> -DSCENE=<file> -DOUTPUT=<image> -DSTATS=<json>
#         [-DEXTRA_ARGS=<;-list>] -P expect_outputs.cmake
foreach(variable EXECUTABLE SCENE OUTPUT STATS)
    if(NOT DEFINED ${variable})
        message(FATAL_ERROR "expect_outputs.cmake: -D${variable}=... is missing")
    endif()
endforeach()

string(REGEX REPLACE "\\.[^.]+$" "_rate.png" heatMap "${OUTPUT}")
file(REMOVE "${OUTPUT}" "${heatMap}" "${STATS}")
set(command "${EXECUTABLE}" --spp 2 --res 12 8 --output "${OUTPUT}" --stats-json "${STATS}"
    ${EXTRA_ARGS} "${SCENE}")
execute_process(COMMAND ${command} RESULT_VARIABLE result OUTPUT_VARIABLE stdout
                ERROR_VARIABLE stderr TIMEOUT 120)
set(report "\ncommand: ${command}\nexit: ${result}\nstderr: [${stderr}]\nstdout: [${stdout}]")

if(NOT result STREQUAL "0")
    message(FATAL_ERROR "expected exit code 0${report}")
endif()
foreach(file "${OUTPUT}" "${heatMap}" "${STATS}")
    if(NOT EXISTS "${file}")
        message(FATAL_ERROR "expected ${file} to be written${report}")
    endif()
endforeach()
if(NOT stdout MATCHES "Mrays/s" OR NOT stdout MATCHES "camera, [0-9]+ extension, [0-9]+ shadow")
    message(FATAL_ERROR "expected the summary with Mrays/s and rays by kind${report}")
endif()

file(READ "${STATS}" json)
string(JSON width GET "${json}" settings width)
string(JSON cameraRays GET "${json}" render rays camera)
string(JSON samples GET "${json}" render samplesTaken)
if(NOT width EQUAL 12 OR NOT cameraRays EQUAL 192 OR NOT samples EQUAL 192)
    message(FATAL_ERROR "stats JSON: width ${width}, camera rays ${cameraRays}, samples "
                        "${samples}; expected 12, 192, 192${report}")
endif()
