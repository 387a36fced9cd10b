#pragma once
// The glTF fields whose wrong types the glTF loader (tinygltf) passes over
// without a word, keeping their defaults: checked on the file's JSON first.
#include <string>
#include <string_view>

namespace shadowlab {

/// Throws Error "FILE: JSON.PATH: expected ..." for a material's alphaMode
/// that is not a string, an alphaCutoff that is not a number, a
/// baseColorFactor that is not 4 numbers, or a node's matrix, translation,
/// rotation or scale that is not 16, 3, 4 or 3 numbers. JSON that does not
/// parse is left to the loader, which names its error.
void checkGltfTypes(std::string_view json, const std::string& file);

} // namespace shadowlab
