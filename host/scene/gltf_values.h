// gltf_values.h — checked reads of extension and extras JSON (tinygltf::Value), which tinygltf
// keeps untyped: a missing member gives the default its specification names, a member of the
// wrong type or out of range one GltfProblem line naming the place and the member.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace vkpt::gltf {

// The object `name` in an extensions map, or nullptr when the map has no such entry.
const tinygltf::Value* findExtension(const tinygltf::ExtensionMap& extensions,
                                     const std::string& name);

// The member `key` of `object`, or nullptr when absent or when `object` is not a JSON object.
const tinygltf::Value* findMember(const tinygltf::Value& object, const std::string& key);

// A finite number; `fallback` when absent. `where` starts the message ("light 2").
double readNumber(const tinygltf::Value& object, const std::string& key, double fallback,
                  const std::string& where);

// An array of exactly fallback.size() finite numbers; `fallback` when absent.
std::vector<double> readNumbers(const tinygltf::Value& object, const std::string& key,
                                const std::vector<double>& fallback, const std::string& where);

// A non-negative integer (a glTF index); -1 when absent.
int readIndex(const tinygltf::Value& object, const std::string& key, const std::string& where);

// A string; `fallback` when absent.
std::string readString(const tinygltf::Value& object, const std::string& key,
                       const std::string& fallback, const std::string& where);

// The element `index` of a document-level array such as extensions.KHR_implicit_shapes.shapes,
// or a GltfProblem "<where>: <what> <index> does not exist (the file has <n> <what>s)".
const tinygltf::Value& arrayElement(const tinygltf::Value& array, int index,
                                    const std::string& what, const std::string& where);

} // namespace vkpt::gltf
