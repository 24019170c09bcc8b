#include "geometry/gltf_draco.hpp"

#include <cstring>
#include <memory>
#include <new>

#include <draco/compression/decode.h>

#include "geometry/gltf_document.hpp"
#include "gfield/located_json.hpp"

namespace gfield {
namespace {

using nlohmann::json;

/// Bytes of glTF component type `type`.
size_t component_size(int type) {
  return size_t(gltf_component_bytes(type));
}

/// Components of glTF accessor type `type`.
int type_components(const std::string& type) {
  return int(gltf_type_components(type));
}

/// Writes `components` values of point `point` of `attribute` as glTF component type `type` to
/// `out`; false when Draco cannot convert them (out of the type's range).
bool write_point(const draco::PointAttribute& attribute, draco::PointIndex point, int type,
                 int components, char* out) {
  const draco::AttributeValueIndex value = attribute.mapped_index(point);
  const auto convert = [&](auto sample) {
    using T = decltype(sample);
    T values[16];
    if (!attribute.ConvertValue<T>(value, std::int8_t(components), values))
      return false;
    std::memcpy(out, values, sizeof(T) * size_t(components));
    return true;
  };
  switch (type) {
    case 5120:
      return convert(std::int8_t());
    case 5121:
      return convert(std::uint8_t());
    case 5122:
      return convert(std::int16_t());
    case 5123:
      return convert(std::uint16_t());
    case 5125:
      return convert(std::uint32_t());
    default:
      return convert(float());
  }
}

/// The bytes of accessor `accessor` from Draco attribute `attribute`; "" with `what`.
bool attribute_bytes(const draco::Mesh& mesh, const draco::PointAttribute& attribute,
                     const json& accessor, std::string& bytes, std::string& what) {
  const int type = accessor["componentType"].get<int>();
  const int components = type_components(accessor["type"].get<std::string>());
  const bool float_data =
      attribute.data_type() == draco::DT_FLOAT32 || attribute.data_type() == draco::DT_FLOAT64;
  if (accessor["count"].get<std::uint64_t>() != mesh.num_points() ||
      attribute.num_components() < components || (type != 5126 && float_data) ||
      (!attribute.is_mapping_identity() && attribute.indices_map_size() < mesh.num_points())) {
    what = "Draco decoded " + std::to_string(mesh.num_points()) + " points of " +
           std::to_string(int(attribute.num_components())) + (float_data ? " float" : " integer") +
           " components for an accessor of " +
           std::to_string(accessor["count"].get<std::uint64_t>()) + " elements of " +
           std::to_string(components);
    return false;
  }
  const size_t element = component_size(type) * size_t(components);
  bytes.assign(element * mesh.num_points(), '\0');
  for (draco::PointIndex p(0); p < mesh.num_points(); ++p) {
    if (!write_point(attribute, p, type, components, bytes.data() + element * p.value())) {
      what = "a Draco value does not fit the accessor's component type";
      return false;
    }
  }
  return true;
}

/// The bytes of index accessor `accessor` from the faces of `mesh`; false with `what`.
bool index_bytes(const draco::Mesh& mesh, const json& accessor, std::string& bytes,
                 std::string& what) {
  const int type = accessor["componentType"].get<int>();
  const size_t size = component_size(type);
  const std::uint64_t limit = type == 5121 ? 0xFF : type == 5123 ? 0xFFFF : 0xFFFFFFFF;
  if (accessor["count"].get<std::uint64_t>() != std::uint64_t(mesh.num_faces()) * 3 ||
      accessor["type"] != "SCALAR" || (type != 5121 && type != 5123 && type != 5125)) {
    what = "Draco decoded " + std::to_string(mesh.num_faces()) +
           " triangles for an index accessor of " +
           std::to_string(accessor["count"].get<std::uint64_t>()) + " elements";
    return false;
  }
  bytes.assign(size * 3 * mesh.num_faces(), '\0');
  for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = mesh.face(f)[k].value();
      if (v >= mesh.num_points() || v > limit) {
        what = "Draco decoded a corner index " + std::to_string(v) + " beyond the " +
               std::to_string(mesh.num_points()) + " points or the accessor's component type";
        return false;
      }
      std::memcpy(bytes.data() + size * (3 * f.value() + size_t(k)), &v, size);  // little-endian
    }
  }
  return true;
}

/// Decodes `compressed` into a Draco triangle mesh; false with `what`.
bool decode_mesh(const std::string& compressed, std::unique_ptr<draco::Mesh>& mesh,
                 std::string& what) {
  draco::DecoderBuffer peek;
  peek.Init(compressed.data(), compressed.size());
  const auto type = draco::Decoder::GetEncodedGeometryType(&peek);
  if (!type.ok() || type.value() != draco::TRIANGULAR_MESH) {
    what = type.ok() ? "the Draco data hold a point cloud, not a triangle mesh"
                     : "not Draco data (" + type.status().error_msg_string() + ")";
    return false;
  }
  draco::DecoderBuffer buffer;
  buffer.Init(compressed.data(), compressed.size());
  draco::Decoder decoder;
  try {
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok()) {
      what = "Draco cannot decode the data (" + decoded.status().error_msg_string() + ")";
      return false;
    }
    mesh = std::move(decoded).value();
  } catch (const std::bad_alloc&) {
    what = "Draco ran out of memory decoding the data (corrupt counts?)";
    return false;
  }
  return true;
}

}  // namespace

bool decode_draco_primitive(const json& document, size_t mesh_index, size_t primitive_index,
                            const std::string& compressed, std::map<size_t, std::string>& accessors,
                            JsonFailure& failure) {
  const json& primitive = document["meshes"][mesh_index]["primitives"][primitive_index];
  const json& ext = primitive["extensions"]["KHR_draco_mesh_compression"];
  failure.pointer = json_pointer_child(
      json_pointer_child(
          json_pointer_child(
              json_pointer_child(json_pointer_child("/meshes", mesh_index), "primitives"),
              primitive_index),
          "extensions"),
      "KHR_draco_mesh_compression");
  const json* names = json_at(ext, {"attributes"});
  const int mode = primitive.value("mode", 4);
  if (names == nullptr || !names->is_object() || !primitive.contains("indices") || mode != 4) {
    failure.what = "a Draco primitive needs attributes, indices and mode TRIANGLES";
    return false;
  }
  std::unique_ptr<draco::Mesh> mesh;
  std::string what;
  if (!decode_mesh(compressed, mesh, what) ||
      !index_bytes(*mesh, document["accessors"][primitive["indices"].get<size_t>()],
                   accessors[primitive["indices"].get<size_t>()], what)) {
    failure.what = what;
    return false;
  }
  for (auto it = names->begin(); it != names->end(); ++it) {
    const json* accessor = json_at(primitive, {"attributes", it.key().c_str()});
    const draco::PointAttribute* attribute =
        it.value().is_number_integer() && it.value().get<std::int64_t>() >= 0 &&
                it.value().get<std::int64_t>() <= 0xFFFFFFFF
            ? mesh->GetAttributeByUniqueId(it.value().get<std::uint32_t>())
            : nullptr;
    if (accessor == nullptr || attribute == nullptr) {
      failure.what = "attributes." + it.key() + ": " +
                     (accessor == nullptr ? "the primitive has no such attribute"
                                          : "no Draco attribute of that id");
      return false;
    }
    const size_t index = accessor->get<size_t>();
    if (!attribute_bytes(*mesh, *attribute, document["accessors"][index], accessors[index], what)) {
      failure.what = "attributes." + it.key() + ": " + what;
      return false;
    }
  }
  return true;
}

}  // namespace gfield
