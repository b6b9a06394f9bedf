# vkpt_kernels.cmake — vkpt_add_kernels(): GLSL compute kernels → SPIR-V at build time, embedded
# in a static library so that executables run from any folder with no .spv files beside them.
#
#   vkpt_add_kernels(<target>
#       NAMESPACE <c++ namespace>      e.g. vkpt::kernels; must differ between libraries
#       SOURCES <file.comp>...         kernel name = file name without .comp (snake_case)
#       [INCLUDE_DIRS <dir>...]        searched after the including file's folder and shaders/
#       [DEFINES <NAME[=VALUE]>...]    -D options for every kernel of the library
#       [OPTIMIZE])                    run spirv-opt -O over each kernel's SPIR-V
#
# Produces the static library <target> and its header "<target>.h", which declares
# <namespace>::embeddedKernels() and <namespace>::findKernel(name). Every kernel is compiled with
# glslangValidator -V --target-env vulkan1.2 (plus -g in Debug); a GLSL error fails the build.
# glslang writes a depfile listing every #include, so editing shared/host_device.h recompiles
# exactly the kernels that include it. Specialisation constants need nothing here: kernels
# declare layout(constant_id = N) and the host folds their values into the module when it
# creates the pipeline (host/gpu/spirv_specialise.h).
# OPTIMIZE is for builds whose DEFINES turn features into constants: glslang leaves the code
# those constants cut off in the module, and spirv-opt's inlining and dead-branch elimination
# remove it, so that a driver never translates it (docs/gpu.md, "Pipelines").

find_program(VKPT_GLSLANG_VALIDATOR glslangValidator REQUIRED
             DOC "glslangValidator from glslang-tools, compiles GLSL kernels to SPIR-V")
find_program(VKPT_SPIRV_OPT spirv-opt REQUIRED
             DOC "spirv-opt from spirv-tools, optimises the kernels built for a feature set")

# The include root of every kernel: "shared/rng.h", "lib/buffers.glsl".
get_filename_component(shader_root ${CMAKE_CURRENT_LIST_DIR}/.. ABSOLUTE)
set(VKPT_SHADER_ROOT ${shader_root} CACHE INTERNAL "")
set(VKPT_EMBED_SPIRV_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/embed_spirv.cmake CACHE INTERNAL "")

# "trace_closest" → "kTraceClosest", the C++ name of the kernel's word array.
function(_vkpt_kernel_symbol name out_var)
    string(REPLACE "_" ";" parts "${name}")
    set(symbol "k")
    foreach(part IN LISTS parts)
        string(SUBSTRING "${part}" 0 1 first)
        string(SUBSTRING "${part}" 1 -1 rest)
        string(TOUPPER "${first}" first)
        string(APPEND symbol "${first}${rest}")
    endforeach()
    set(${out_var} ${symbol} PARENT_SCOPE)
endfunction()

# One custom command per kernel: .comp → .spv (with depfile) → .spv.cpp (the word array).
function(_vkpt_compile_kernel source out_dir namespace glslang_flags optimize out_cpp out_name
         out_symbol)
    cmake_path(ABSOLUTE_PATH source BASE_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}
               OUTPUT_VARIABLE source)
    cmake_path(GET source STEM name)
    if(NOT name MATCHES "^[a-z][a-z0-9_]*$")
        message(FATAL_ERROR "vkpt_add_kernels: kernel file name '${name}' is not snake_case")
    endif()
    _vkpt_kernel_symbol(${name} symbol)
    set(spv ${out_dir}/${name}.spv)
    set(cpp ${out_dir}/${name}.spv.cpp)
    cmake_path(RELATIVE_PATH source BASE_DIRECTORY ${PROJECT_SOURCE_DIR}
               OUTPUT_VARIABLE source_label)
    set(optimize_command)
    if(optimize)
        set(optimize_command COMMAND ${VKPT_SPIRV_OPT} -O ${spv} -o ${spv})
    endif()
    add_custom_command(
        OUTPUT ${spv}
        COMMAND ${VKPT_GLSLANG_VALIDATOR} -V --quiet ${glslang_flags}
                --depfile ${spv}.d -o ${spv} ${source}
        ${optimize_command}
        MAIN_DEPENDENCY ${source}
        DEPENDS ${VKPT_GLSLANG_VALIDATOR}
        DEPFILE ${spv}.d
        COMMENT "Compiling kernel ${source_label}"
        VERBATIM COMMAND_EXPAND_LISTS)
    add_custom_command(
        OUTPUT ${cpp}
        COMMAND ${CMAKE_COMMAND} -DSPV=${spv} -DOUTPUT=${cpp} -DSYMBOL=${symbol}
                -DNAMESPACE=${namespace} -DSOURCE_LABEL=${source_label}
                -P ${VKPT_EMBED_SPIRV_SCRIPT}
        DEPENDS ${spv} ${VKPT_EMBED_SPIRV_SCRIPT}
        COMMENT "Embedding kernel ${name}"
        VERBATIM)
    set(${out_cpp} ${cpp} PARENT_SCOPE)
    set(${out_name} ${name} PARENT_SCOPE)
    set(${out_symbol} ${symbol} PARENT_SCOPE)
endfunction()

function(vkpt_add_kernels target)
    cmake_parse_arguments(ARG "OPTIMIZE" "NAMESPACE" "SOURCES;INCLUDE_DIRS;DEFINES" ${ARGN})
    if(NOT ARG_NAMESPACE OR NOT ARG_SOURCES)
        message(FATAL_ERROR "vkpt_add_kernels(${target}): NAMESPACE and SOURCES are required")
    endif()
    set(out_dir ${CMAKE_CURRENT_BINARY_DIR}/${target})
    set(flags --target-env vulkan1.2 -I${VKPT_SHADER_ROOT} "$<$<CONFIG:Debug>:-g>")
    foreach(dir IN LISTS ARG_INCLUDE_DIRS)
        cmake_path(ABSOLUTE_PATH dir BASE_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR})
        list(APPEND flags -I${dir})
    endforeach()
    foreach(define IN LISTS ARG_DEFINES)
        list(APPEND flags -D${define})
    endforeach()

    set(cpps)
    set(names)
    set(symbols)
    foreach(source IN LISTS ARG_SOURCES)
        _vkpt_compile_kernel(${source} ${out_dir} ${ARG_NAMESPACE} "${flags}" ${ARG_OPTIMIZE} cpp
                             name symbol)
        if(name IN_LIST names)
            message(FATAL_ERROR "vkpt_add_kernels(${target}): two kernels named '${name}'")
        endif()
        list(APPEND cpps ${cpp})
        list(APPEND names ${name})
        list(APPEND symbols ${symbol})
    endforeach()

    _vkpt_write_kernel_registry(${target} ${out_dir} ${ARG_NAMESPACE} "${names}" "${symbols}")
    add_library(${target} STATIC ${cpps} ${out_dir}/${target}_registry.cpp ${out_dir}/${target}.h)
    target_include_directories(${target} PUBLIC ${out_dir})
    target_link_libraries(${target} PRIVATE vkpt_common vkpt_warnings)
endfunction()

# The header and the name lookup depend only on the list of kernels, so they are written at
# configure time (file(CONFIGURE) rewrites them only when their text changes).
function(_vkpt_write_kernel_registry target out_dir namespace names symbols)
    set(constants "")
    set(declarations "")
    set(entries "")
    foreach(name symbol IN ZIP_LISTS names symbols)
        string(APPEND constants "inline constexpr std::string_view ${symbol}Name = \"${name}\";\n")
        string(APPEND declarations "extern const std::uint32_t ${symbol}[];\n")
        string(APPEND declarations "extern const std::size_t ${symbol}WordCount;\n")
        string(APPEND entries "        {\"${name}\", {${symbol}, ${symbol}WordCount}},\n")
    endforeach()
    set(NAMESPACE ${namespace})
    set(TARGET ${target})
    set(KERNEL_NAME_CONSTANTS "${constants}")
    set(KERNEL_DECLARATIONS "${declarations}")
    set(KERNEL_ENTRIES "${entries}")
    file(READ ${VKPT_SHADER_ROOT}/cmake/kernel_registry.h.in header_template)
    file(READ ${VKPT_SHADER_ROOT}/cmake/kernel_registry.cpp.in source_template)
    file(CONFIGURE OUTPUT ${out_dir}/${target}.h CONTENT "${header_template}" @ONLY)
    file(CONFIGURE OUTPUT ${out_dir}/${target}_registry.cpp CONTENT "${source_template}" @ONLY)
    # Re-run configure when the templates change.
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
                 ${VKPT_SHADER_ROOT}/cmake/kernel_registry.h.in
                 ${VKPT_SHADER_ROOT}/cmake/kernel_registry.cpp.in)
endfunction()
