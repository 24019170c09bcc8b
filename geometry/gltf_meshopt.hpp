#pragma once
// EXT_meshopt_compression buffer views decoded with meshoptimizer's decoders (Debian's
// libmeshoptimizer), after gfield has checked what the extension claims. Internal to the glTF
// code (gltf_decompress.hpp).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/gltf_buffers.hpp"
#include "geometry/gltf_checks.hpp"

namespace gfield {

/// Decodes buffer view `index` of `document`, whose EXT_meshopt_compression object names the
/// compressed bytes in `buffers`, into `decoded` (count * byteStride bytes: the view's
/// byteLength). Checked before meshoptimizer runs: mode ATTRIBUTES (byteStride a multiple of 4
/// up to 256), TRIANGLES (count a multiple of 3) or INDICES (byteStride 2 or 4); a filter NONE,
/// OCTAHEDRAL (byteStride 4 or 8), QUATERNION (8) or EXPONENTIAL (a multiple of 4) on attributes
/// only; the compressed range within a buffer that has bytes; count * byteStride equal to the
/// view's byteLength. False with `failure` at the extension's pointer.
bool decode_meshopt_view(const nlohmann::json& document, size_t index,
                         const std::vector<GltfBufferBytes>& buffers, std::string& decoded,
                         JsonFailure& failure);

}  // namespace gfield
