#pragma once
// KHR_draco_mesh_compression primitives decoded with Debian's libdraco, after gfield has checked
// what the extension and the primitive's accessors claim, and checked again against what Draco
// decoded before any of it is used. Internal to the glTF code (gltf_decompress.hpp).

#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "geometry/gltf_checks.hpp"

namespace gfield {

/// Decodes the Draco bytes `compressed` of primitive `primitive` of mesh `mesh` of `document`
/// into one byte string per accessor it fills (`accessors`: accessor index -> count elements of
/// its componentType and type, tightly packed): the primitive's indices and each attribute the
/// extension's "attributes" names by Draco id. Checked: the primitive is TRIANGLES with indices,
/// the named attributes are the primitive's, the bytes hold a Draco triangle mesh (not a point
/// cloud), and what Draco decoded matches the accessors (faces x 3 = the indices' count, points =
/// each attribute's count, components at least the accessor's, indices within the points and
/// within their component type, integer accessors from integer Draco data). False with `failure`
/// at the extension's pointer.
bool decode_draco_primitive(const nlohmann::json& document, size_t mesh, size_t primitive,
                            const std::string& compressed, std::map<size_t, std::string>& accessors,
                            JsonFailure& failure);

}  // namespace gfield
