// PLY (ASCII, binary little and big endian): the "vertex" element's x, y, z and the "face"
// element's "vertex_indices" (or "vertex_index") list; other elements and properties are read
// past. Element counts and list lengths are checked against the bytes left before any loop.

#include <algorithm>
#include <bit>
#include <cstring>
#include <vector>

#include "geometry/ply_header.hpp"
#include "geometry/text_scan.hpp"
#include "gfield/limits.hpp"

namespace gfield {
namespace {

/// The values of the data section, in the file's format. ASCII values are words (2 bytes at
/// least, with their separator); binary ones are read with bounds checks.
class PlyValues {
 public:
  PlyValues(std::string_view data, PlyFormat format, size_t header_lines)
      : data_(data), format_(format), words_(data), line_offset_(header_lines) {}

  bool ascii() const { return format_ == PlyFormat::kAscii; }
  size_t line() const { return ascii() ? line_offset_ + words_.line() : 0; }
  std::uint64_t remaining() const {
    return ascii() ? words_.remaining() : data_.size() - position_;
  }
  /// Fewest bytes one value of `type` takes.
  std::uint64_t min_bytes(PlyType type) const { return ascii() ? 2 : ply_type_size(type); }

  bool number(PlyType type, double& value, std::string& what) {
    if (ascii()) {
      std::string_view word;
      if (!words_.next(word) || !text::parse_double(word, value)) {
        what = word.empty() ? "truncated data" : "value " + text::quoted(word) + " is not a number";
        return false;
      }
      return true;
    }
    unsigned char bytes[8];
    const size_t size = ply_type_size(type);
    if (data_.size() - position_ < size) {
      what = "truncated data";
      return false;
    }
    std::memcpy(bytes, data_.data() + position_, size);
    position_ += size;
    if ((format_ == PlyFormat::kBinaryBigEndian) == (std::endian::native == std::endian::little)) {
      std::reverse(bytes, bytes + size);
    }
    value = decode(type, bytes);
    return true;
  }

  bool integer(PlyType type, std::int64_t& value, std::string& what) {
    if (ascii()) {
      std::string_view word;
      if (!words_.next(word) || !text::parse_int64(word, value)) {
        what =
            word.empty() ? "truncated data" : "value " + text::quoted(word) + " is not an integer";
        return false;
      }
      return true;
    }
    double v = 0.0;
    if (!number(type, v, what)) {
      return false;
    }
    value = std::int64_t(v);  // integer types of at most 32 bits: exact
    return true;
  }

 private:
  static double decode(PlyType type, const unsigned char* b) {
    switch (type) {
      case PlyType::kInt8:
        return double(std::int8_t(b[0]));
      case PlyType::kUint8:
        return double(b[0]);
      case PlyType::kInt16:
        return double(load<std::int16_t>(b));
      case PlyType::kUint16:
        return double(load<std::uint16_t>(b));
      case PlyType::kInt32:
        return double(load<std::int32_t>(b));
      case PlyType::kUint32:
        return double(load<std::uint32_t>(b));
      case PlyType::kFloat32:
        return double(load<float>(b));
      case PlyType::kFloat64:
        return load<double>(b);
    }
    return 0.0;
  }
  template <class T>
  static T load(const unsigned char* b) {
    T v;
    std::memcpy(&v, b, sizeof(T));
    return v;
  }

  std::string_view data_;
  PlyFormat format_;
  size_t position_ = 0;
  text::WordStream words_;
  size_t line_offset_;
};

/// Fewest bytes one instance of `element` takes.
std::uint64_t min_element_bytes(const PlyElement& element, const PlyValues& values) {
  std::uint64_t bytes = 0;
  for (const PlyProperty& p : element.properties) {
    bytes += values.min_bytes(p.list ? p.count_type : p.type);
  }
  return bytes;
}

/// Where the x, y, z of "vertex" and the index list of "face" are (-1: absent).
struct Roles {
  int x = -1, y = -1, z = -1;
  int indices = -1;
};

/// The role of property `p` of `element`, or null.
int* role_of(const PlyElement& element, const PlyProperty& p, Roles& roles) {
  if (element.name == "vertex") {
    return p.name == "x" ? &roles.x : p.name == "y" ? &roles.y : p.name == "z" ? &roles.z : nullptr;
  }
  const bool indices = p.name == "vertex_indices" || p.name == "vertex_index";
  return element.name == "face" && indices ? &roles.indices : nullptr;
}

bool find_roles(const PlyElement& element, Roles& roles, std::string& what) {
  for (size_t i = 0; i < element.properties.size(); ++i) {
    const PlyProperty& p = element.properties[i];
    int* role = role_of(element, p, roles);
    if (role == nullptr) {
      continue;
    }
    const bool want_list = element.name == "face";
    if (p.list != want_list || (want_list && !ply_type_is_integer(p.type)) || *role >= 0) {
      what = "property " + text::quoted(p.name) + " of element " + text::quoted(element.name) +
             (want_list ? " must be one list of integers" : " must be one scalar");
      return false;
    }
    *role = int(i);
  }
  if (element.name == "vertex" && (roles.x < 0 || roles.y < 0 || roles.z < 0)) {
    what = "the vertex element lacks x, y or z";
    return false;
  }
  return true;
}

/// Reads (or reads past) one list; its items go to `items` when not null.
bool read_list(PlyValues& values, const PlyProperty& p, std::vector<std::int64_t>* items,
               std::string& what) {
  std::int64_t length = 0;
  if (!values.integer(p.count_type, length, what)) {
    return false;
  }
  if (length < 0 || std::uint64_t(length) > values.remaining() / values.min_bytes(p.type)) {
    what = "list length " + std::to_string(length) + " of " + text::quoted(p.name) +
           " is negative or beyond the end of the file";
    return false;
  }
  for (std::int64_t k = 0; k < length; ++k) {
    double value = 0.0;
    std::int64_t index = 0;
    const bool ok =
        items ? values.integer(p.type, index, what) : values.number(p.type, value, what);
    if (!ok) {
      return false;
    }
    if (items) {
      items->push_back(index);
    }
  }
  return true;
}

bool read_element(PlyValues& values, const PlyElement& element, std::int64_t vertex_count,
                  MeshSoup& soup, ReadFailure& failure) {
  Roles roles;
  if (!find_roles(element, roles, failure.what) ||
      !check_count(element.count, kMaxMeshVertices, min_element_bytes(element, values),
                   values.remaining() + 1, "'" + element.name + "' elements", failure.what)) {
    return false;
  }
  if (element.name == "vertex") {
    soup.mesh.positions.reserve(size_t(element.count));
  }
  std::vector<std::int64_t> corners;
  double xyz[3] = {0.0, 0.0, 0.0};
  for (std::int64_t e = 0; e < element.count && !element.properties.empty(); ++e) {
    corners.clear();
    for (size_t i = 0; i < element.properties.size(); ++i) {
      const PlyProperty& p = element.properties[i];
      const bool is_indices = int(i) == roles.indices;
      double value = 0.0;
      const bool ok = p.list ? read_list(values, p, is_indices ? &corners : nullptr, failure.what)
                             : values.number(p.type, value, failure.what);
      failure.line = values.line();
      if (!ok) {
        failure.what = element.name + " " + std::to_string(e) + ": " + failure.what;
        return false;
      }
      const int k = int(i) == roles.x ? 0 : int(i) == roles.y ? 1 : int(i) == roles.z ? 2 : -1;
      if (k >= 0) {
        xyz[k] = value;
      }
    }
    bool ok = true;
    if (element.name == "vertex") {
      ok = add_vertex(soup, xyz[0], xyz[1], xyz[2], failure.what);
    } else if (roles.indices >= 0) {
      for (const std::int64_t index : corners) {
        ok = ok && check_index(index, vertex_count, failure.what);
      }
      ok = ok && add_polygon(soup, corners, failure.what);
    }
    if (!ok) {
      failure.what = element.name + " " + std::to_string(e) + ": " + failure.what;
      return false;
    }
  }
  return true;
}

}  // namespace

bool read_ply(std::string_view data, MeshSoup& soup, ReadFailure& failure) {
  PlyHeader header;
  if (!read_ply_header(data, header, failure)) {
    return false;
  }
  std::int64_t vertex_count = 0;
  int vertex_elements = 0;
  for (const PlyElement& element : header.elements) {
    if (element.name == "vertex") {
      vertex_count = element.count;
      ++vertex_elements;
    }
  }
  if (vertex_elements > 1) {
    failure.what = "more than one vertex element";
    return false;
  }
  PlyValues values(data.substr(header.data_offset), header.format, header.lines);
  for (const PlyElement& element : header.elements) {
    if (!read_element(values, element, vertex_count, soup, failure)) {
      return false;
    }
  }
  failure.line = 0;
  return true;
}

}  // namespace gfield
