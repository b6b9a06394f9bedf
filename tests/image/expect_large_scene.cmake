# expect_large_scene.cmake — a generated scene with an array larger than lavapipe's 128 MiB
# storage-buffer range renders: the textured room of write_room_scene, whose texture coordinates
# (24 bytes per triangle) outgrow one binding above 5.6 million triangles. Checks exit code 0,
# that the array was above the device's maxStorageBufferRange and went into several buffers,
# and that rays hit the scene.
#
#   cmake -DGENERATOR=<write_room_scene> -DVKPT=<vkpt> -DWORK=<directory> -DTRIANGLES=<n>
#         -P expect_large_scene.cmake
foreach(variable GENERATOR VKPT WORK TRIANGLES)
    if(NOT DEFINED ${variable})
        message(FATAL_ERROR "expect_large_scene.cmake: -D${variable}=... is missing")
    endif()
endforeach()

file(MAKE_DIRECTORY "${WORK}")
set(scene "${WORK}/large_room.gltf")
execute_process(COMMAND "${GENERATOR}" --textured --triangles ${TRIANGLES} "${scene}"
                RESULT_VARIABLE result ERROR_VARIABLE stderr TIMEOUT 600)
if(NOT result STREQUAL "0")
    message(FATAL_ERROR "write_room_scene failed (${result}): ${stderr}")
endif()

set(stats "${WORK}/large_room.json")
set(command "${VKPT}" --spp 1 --res 24 24 --max-depth 2 --stats-json "${stats}"
    -o "${WORK}/large_room.pfm" "${scene}")
execute_process(COMMAND ${command} RESULT_VARIABLE result OUTPUT_VARIABLE stdout
                ERROR_VARIABLE stderr TIMEOUT 1500)
file(REMOVE "${scene}" "${WORK}/large_room.bin")
set(report "\ncommand: ${command}\nexit: ${result}\nstderr: [${stderr}]\nstdout: [${stdout}]")
if(NOT result STREQUAL "0")
    message(FATAL_ERROR "expected exit code 0${report}")
endif()

file(READ "${stats}" json)
string(JSON arrays LENGTH "${json}" wavefront sceneBuffers)
math(EXPR last "${arrays} - 1")
set(found FALSE)
foreach(i RANGE ${last})
    string(JSON name GET "${json}" wavefront sceneBuffers ${i} name)
    if(name STREQUAL "triangleUvs")
        string(JSON bytes GET "${json}" wavefront sceneBuffers ${i} bytes)
        string(JSON buffers GET "${json}" wavefront sceneBuffers ${i} buffers)
        set(found TRUE)
    endif()
endforeach()
if(NOT found)
    message(FATAL_ERROR "no triangleUvs among the scene buffers${report}")
endif()
message(STATUS "triangleUvs: ${bytes} bytes in ${buffers} buffers")
# 134217728 bytes: lavapipe's maxStorageBufferRange (128 MiB), as on many GPUs.
if(bytes LESS_EQUAL 134217728 OR buffers LESS 2)
    message(FATAL_ERROR "expected triangleUvs above 128 MiB in several buffers${report}")
endif()
# Camera rays that hit the sphere and walls go on as extension rays; no walk may be cut short.
string(JSON extension GET "${json}" render rays extension)
string(JSON truncated GET "${json}" wavefront truncatedTraversals)
if(NOT extension GREATER 0 OR NOT truncated EQUAL 0)
    message(FATAL_ERROR "expected hits and no truncated walks${report}")
endif()
