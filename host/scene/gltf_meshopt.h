// gltf_meshopt.h — EXT_meshopt_compression: buffer views whose data is stored compressed by
// meshoptimizer's codecs, decoded into the view's own (usually fallback) buffer right after
// parsing, so that everything after reads them as ordinary buffer views.
#pragma once

#include <tiny_gltf.h>

namespace vkpt::gltf {

// Decodes every buffer view that has an EXT_meshopt_compression object (modes ATTRIBUTES,
// TRIANGLES, INDICES; filters NONE, OCTAHEDRAL, QUATERNION, EXPONENTIAL) with libmeshoptimizer
// and writes the result over the view's bytes. Every range is checked first; a stream that does
// not decode is a GltfProblem naming the buffer view.
void decodeMeshoptBufferViews(tinygltf::Model& model);

} // namespace vkpt::gltf
