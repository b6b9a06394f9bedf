// buffers.glsl — declares storage buffers so that the GLSL name, the C++ name and the VkBuffer
// debug name are the same word (bvhNodes, triangles, ...) and every block is std430.
#ifndef VKPT_BUFFERS_GLSL
#define VKPT_BUFFERS_GLSL

// An unsized array `Type name[]` at `binding` of descriptor set 0. The block type is
// name##Buffer, so it never collides with the array's name; readonly/writeonly let the
// compiler (and validation) know which kernels only read or only write a buffer.
#define VKPT_BUFFER(bindingIndex, Type, name)                                                      \
    layout(std430, set = 0, binding = bindingIndex) buffer name##Buffer {                          \
        Type name[];                                                                               \
    };
#define VKPT_READONLY_BUFFER(bindingIndex, Type, name)                                             \
    layout(std430, set = 0, binding = bindingIndex) readonly buffer name##Buffer {                 \
        Type name[];                                                                               \
    };
#define VKPT_WRITEONLY_BUFFER(bindingIndex, Type, name)                                            \
    layout(std430, set = 0, binding = bindingIndex) writeonly buffer name##Buffer {                \
        Type name[];                                                                               \
    };

// A uniform texel buffer of 16-byte texels read with texelFetch(name, index): for arrays that
// every invocation reads at its own index, which lavapipe gathers for 8 invocations at once
// instead of loading word by word (docs/gpu.md).
#define VKPT_TEXEL_BUFFER(bindingIndex, name)                                                      \
    layout(set = 0, binding = bindingIndex) uniform usamplerBuffer name;

#endif // VKPT_BUFFERS_GLSL
