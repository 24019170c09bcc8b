// PLY (ASCII, binary little and big endian): the "vertex" element's x, y, z, texture
// coordinates (u v, s t, texture_u texture_v) and colour (red green blue: 8/16-bit sRGB or
// linear floats), the "face" element's "vertex_indices" (or "vertex_index") list and MeshLab's
// per-corner "texcoord" list, and "comment TextureFile NAME" (the texture of the whole mesh);
// other elements and properties are read past. Element counts and list lengths are checked against
// the bytes left before any loop.

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

/// The scalar properties of "vertex" gfield reads, in Roles::scalars.
enum VertexRole { kX, kY, kZ, kU, kV, kRed, kGreen, kBlue, kVertexRoles };

/// Where the roles are among an element's properties (-1: absent): the vertex's scalars, and the
/// face's index list and texture-coordinate list (MeshLab's "texcoord": u v per corner).
struct Roles {
  int scalars[kVertexRoles] = {-1, -1, -1, -1, -1, -1, -1, -1};
  int indices = -1;
  int texcoord = -1;
};

int vertex_role(const std::string& name) {
  static const std::pair<const char*, VertexRole> kNames[] = {{"x", kX},
                                                              {"y", kY},
                                                              {"z", kZ},
                                                              {"u", kU},
                                                              {"s", kU},
                                                              {"texture_u", kU},
                                                              {"texture_s", kU},
                                                              {"v", kV},
                                                              {"t", kV},
                                                              {"texture_v", kV},
                                                              {"texture_t", kV},
                                                              {"red", kRed},
                                                              {"green", kGreen},
                                                              {"blue", kBlue},
                                                              {"diffuse_red", kRed},
                                                              {"diffuse_green", kGreen},
                                                              {"diffuse_blue", kBlue}};
  for (const auto& [n, role] : kNames) {
    if (name == n) {
      return role;
    }
  }
  return -1;
}

/// The role of property `p` of `element`, or null.
int* role_of(const PlyElement& element, const PlyProperty& p, Roles& roles) {
  if (element.name == "vertex") {
    const int role = vertex_role(p.name);
    return role >= 0 ? &roles.scalars[role] : nullptr;
  }
  if (element.name != "face") {
    return nullptr;
  }
  return p.name == "vertex_indices" || p.name == "vertex_index" ? &roles.indices
         : p.name == "texcoord"                                 ? &roles.texcoord
                                                                : nullptr;
}

bool find_roles(const PlyElement& element, Roles& roles, std::string& what) {
  for (size_t i = 0; i < element.properties.size(); ++i) {
    const PlyProperty& p = element.properties[i];
    int* role = role_of(element, p, roles);
    if (role == nullptr) {
      continue;
    }
    const bool want_list = element.name == "face";
    const bool want_integers = role == &roles.indices;
    if (p.list != want_list || (want_integers && !ply_type_is_integer(p.type)) || *role >= 0) {
      what = "property " + text::quoted(p.name) + " of element " + text::quoted(element.name) +
             (want_integers ? " must be one list of integers"
              : want_list   ? " must be one list"
                            : " must be one scalar");
      return false;
    }
    *role = int(i);
  }
  const int* s = roles.scalars;
  if (element.name == "vertex" && (s[kX] < 0 || s[kY] < 0 || s[kZ] < 0)) {
    what = "the vertex element lacks x, y or z";
    return false;
  }
  if (element.name == "vertex" && ((s[kU] < 0) != (s[kV] < 0) || (s[kRed] < 0) != (s[kGreen] < 0) ||
                                   (s[kRed] < 0) != (s[kBlue] < 0))) {
    what = "the vertex element has only some of u, v or of red, green, blue";
    return false;
  }
  return true;
}

/// Reads (or reads past) one list; its items go to `items` (integers) or `numbers` when not
/// null.
bool read_list(PlyValues& values, const PlyProperty& p, std::vector<std::int64_t>* items,
               std::vector<double>* numbers, std::string& what) {
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
    if (numbers) {
      numbers->push_back(value);
    }
  }
  return true;
}

/// A colour component of `type` as linear: 8 and 16-bit integers are sRGB, floats linear.
double linear_component(double value, PlyType type) {
  if (type == PlyType::kUint8) {
    return srgb_to_linear(float(value / 255.0));
  }
  if (type == PlyType::kUint16) {
    return srgb_to_linear(float(value / 65535.0));
  }
  return value;
}

/// Adds one vertex with its texture coordinates and colour (`scalars` per VertexRole).
bool add_ply_vertex(const PlyElement& element, const Roles& roles, const double* scalars,
                    MeshSoup& soup, std::string& what) {
  if (!add_vertex(soup, scalars[kX], scalars[kY], scalars[kZ], what) ||
      (roles.scalars[kU] >= 0 && !add_uv(soup, scalars[kU], scalars[kV], what))) {
    return false;
  }
  if (roles.scalars[kRed] < 0) {
    return true;
  }
  glm::dvec3 color;
  for (int k = 0; k < 3; ++k) {
    const PlyType type = element.properties[size_t(roles.scalars[kRed + k])].type;
    color[k] = linear_component(scalars[kRed + k], type);
  }
  return set_vertex_color(soup, color, what);
}

/// Adds one face: its corners (checked against the vertex count) with the vertices' texture
/// coordinates or its own (`texcoord`, u v per corner).
bool add_ply_face(const std::vector<std::int64_t>& corners, const std::vector<double>& texcoord,
                  std::int64_t vertex_count, MeshSoup& soup, std::string& what) {
  for (const std::int64_t index : corners) {
    if (!check_index(index, vertex_count, what)) {
      return false;
    }
  }
  std::vector<std::int64_t> uvs;
  if (!texcoord.empty()) {
    if (texcoord.size() != 2 * corners.size()) {
      what = "texcoord holds " + std::to_string(texcoord.size()) + " numbers for " +
             std::to_string(corners.size()) + " corners (2 per corner)";
      return false;
    }
    for (size_t c = 0; c < corners.size(); ++c) {
      uvs.push_back(std::int64_t(soup.uvs.size()));
      if (!add_uv(soup, texcoord[2 * c], texcoord[2 * c + 1], what)) {
        return false;
      }
    }
  } else if (!soup.uvs.empty() && std::int64_t(soup.uvs.size()) == vertex_count) {
    uvs = corners;  // per-vertex texture coordinates
  }
  return add_polygon(soup, corners, what, {std::span<const std::int64_t>(uvs), -1});
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
  std::vector<double> texcoord;
  double scalars[kVertexRoles] = {};
  for (std::int64_t e = 0; e < element.count && !element.properties.empty(); ++e) {
    corners.clear();
    texcoord.clear();
    for (size_t i = 0; i < element.properties.size(); ++i) {
      const PlyProperty& p = element.properties[i];
      double value = 0.0;
      const bool ok = p.list
                          ? read_list(values, p, int(i) == roles.indices ? &corners : nullptr,
                                      int(i) == roles.texcoord ? &texcoord : nullptr, failure.what)
                          : values.number(p.type, value, failure.what);
      failure.line = values.line();
      if (!ok) {
        failure.what = element.name + " " + std::to_string(e) + ": " + failure.what;
        return false;
      }
      for (int k = 0; k < kVertexRoles; ++k) {
        scalars[k] = int(i) == roles.scalars[k] ? value : scalars[k];
      }
    }
    bool ok = true;
    if (element.name == "vertex") {
      ok = add_ply_vertex(element, roles, scalars, soup, failure.what);
    } else if (roles.indices >= 0) {
      ok = add_ply_face(corners, texcoord, vertex_count, soup, failure.what);
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
  soup.texture_files = header.texture_files;
  if (!soup.vertex_color.empty()) {
    soup.vertex_color.resize(soup.mesh.positions.size(), glm::vec3(1.0f));
  }
  failure.line = 0;
  return true;
}

}  // namespace gfield
