#pragma once
// The header of a PLY file: format, elements and their properties, where the data starts.
// Internal to the PLY reader (ply_reader.cpp).

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/mesh_readers.hpp"

namespace gfield {

enum class PlyFormat { kAscii, kBinaryLittleEndian, kBinaryBigEndian };
enum class PlyType { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::kFloat32;  ///< of the value, or of a list's items
  bool list = false;
  PlyType count_type = PlyType::kUint8;  ///< of a list's length
};

struct PlyElement {
  std::string name;
  std::int64_t count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  PlyFormat format = PlyFormat::kAscii;
  std::vector<PlyElement> elements;
  std::vector<std::string> texture_files;  ///< "comment TextureFile NAME" lines (MeshLab)
  size_t data_offset = 0;                  ///< first byte after "end_header\n"
  size_t lines = 0;                        ///< header lines, for the line numbers of ASCII data
};

/// At most this many elements, and properties per element.
inline constexpr size_t kMaxPlyElements = 1024;
inline constexpr size_t kMaxPlyProperties = 1024;

/// Bytes of one value of `type` in binary PLY.
size_t ply_type_size(PlyType type);
/// True for the integer types.
bool ply_type_is_integer(PlyType type);

/// Parses and checks the header: "ply", one "format" line, "element NAME COUNT" lines each followed
/// by its "property TYPE NAME" / "property list COUNT_TYPE TYPE NAME" lines (a property before any
/// element is an error), "comment"/"obj_info" lines, "end_header". Counts must be integers in
/// [0, kMaxMeshVertices]; the file must end the header.
bool read_ply_header(std::string_view data, PlyHeader& header, ReadFailure& failure);

}  // namespace gfield
