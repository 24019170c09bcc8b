#include "geometry/ply_header.hpp"

#include "geometry/text_scan.hpp"
#include "gfield/limits.hpp"

namespace gfield {
namespace {

bool parse_type(std::string_view word, PlyType& type) {
  static const std::pair<std::string_view, PlyType> kNames[] = {
      {"char", PlyType::kInt8},      {"int8", PlyType::kInt8},       {"uchar", PlyType::kUint8},
      {"uint8", PlyType::kUint8},    {"short", PlyType::kInt16},     {"int16", PlyType::kInt16},
      {"ushort", PlyType::kUint16},  {"uint16", PlyType::kUint16},   {"int", PlyType::kInt32},
      {"int32", PlyType::kInt32},    {"uint", PlyType::kUint32},     {"uint32", PlyType::kUint32},
      {"float", PlyType::kFloat32},  {"float32", PlyType::kFloat32}, {"double", PlyType::kFloat64},
      {"float64", PlyType::kFloat64}};
  for (const auto& [name, t] : kNames) {
    if (word == name) {
      type = t;
      return true;
    }
  }
  return false;
}

bool read_format(text::Words& words, PlyHeader& header, std::string& what) {
  std::string_view format, version;
  words.next(format);
  if (format == "ascii") {
    header.format = PlyFormat::kAscii;
  } else if (format == "binary_little_endian") {
    header.format = PlyFormat::kBinaryLittleEndian;
  } else if (format == "binary_big_endian") {
    header.format = PlyFormat::kBinaryBigEndian;
  } else {
    what = "unknown PLY format " + text::quoted(format);
    return false;
  }
  if (!words.next(version) || version != "1.0" || !words.empty()) {
    what = "unsupported PLY version (expected \"format " + std::string(format) + " 1.0\")";
    return false;
  }
  return true;
}

bool read_element(text::Words& words, PlyHeader& header, std::string& what) {
  std::string_view name, count;
  PlyElement element;
  if (!words.next(name) || !words.next(count) || !text::parse_int64(count, element.count) ||
      !words.empty()) {
    what = "malformed element line (expected \"element NAME COUNT\")";
    return false;
  }
  if (element.count < 0 || element.count > kMaxMeshVertices) {
    what = "element " + text::quoted(name) + " count " + std::to_string(element.count) +
           " is not in [0, " + std::to_string(kMaxMeshVertices) + "]";
    return false;
  }
  if (header.elements.size() == kMaxPlyElements) {
    what = "more than " + std::to_string(kMaxPlyElements) + " elements";
    return false;
  }
  element.name = std::string(name);
  header.elements.push_back(std::move(element));
  return true;
}

bool read_property(text::Words& words, PlyHeader& header, std::string& what) {
  if (header.elements.empty()) {
    what = "a property before any element";
    return false;
  }
  std::vector<PlyProperty>& properties = header.elements.back().properties;
  if (properties.size() == kMaxPlyProperties) {
    what = "more than " + std::to_string(kMaxPlyProperties) + " properties in one element";
    return false;
  }
  PlyProperty property;
  std::string_view type, count_type, name;
  words.next(type);
  property.list = type == "list";
  bool ok = true;
  if (property.list) {
    ok = words.next(count_type) && parse_type(count_type, property.count_type) &&
         ply_type_is_integer(property.count_type);
    words.next(type);
  }
  ok = ok && parse_type(type, property.type) && words.next(name) && words.empty();
  if (!ok) {
    what =
        "malformed property line (expected \"property TYPE NAME\" or \"property list "
        "COUNT_TYPE TYPE NAME\" with COUNT_TYPE an integer type)";
    return false;
  }
  property.name = std::string(name);
  properties.push_back(std::move(property));
  return true;
}

}  // namespace

size_t ply_type_size(PlyType type) {
  switch (type) {
    case PlyType::kInt8:
    case PlyType::kUint8:
      return 1;
    case PlyType::kInt16:
    case PlyType::kUint16:
      return 2;
    case PlyType::kInt32:
    case PlyType::kUint32:
    case PlyType::kFloat32:
      return 4;
    case PlyType::kFloat64:
      return 8;
  }
  return 1;
}

bool ply_type_is_integer(PlyType type) {
  return type != PlyType::kFloat32 && type != PlyType::kFloat64;
}

bool read_ply_header(std::string_view data, PlyHeader& header, ReadFailure& failure) {
  text::Lines lines(data);
  std::string_view line;
  if (!lines.next(line) || line != "ply") {
    failure = {1, "not a PLY file (the first line is not \"ply\")"};
    return false;
  }
  bool format_seen = false;
  while (lines.next(line)) {
    failure.line = lines.number();
    text::Words words(line);
    std::string_view keyword;
    words.next(keyword);
    bool ok = true;
    if (keyword == "format" && !format_seen) {
      ok = format_seen = read_format(words, header, failure.what);
    } else if (keyword == "element" && format_seen) {
      ok = read_element(words, header, failure.what);
    } else if (keyword == "property" && format_seen) {
      ok = read_property(words, header, failure.what);
    } else if (keyword == "end_header" && format_seen && words.empty()) {
      if (!lines.line_ended()) {
        failure.what = "truncated after end_header";
        return false;
      }
      header.data_offset = data.size() - lines.remaining();
      header.lines = lines.number();
      failure.line = 0;
      return true;
    } else if (keyword == "comment") {
      std::string_view word, file;
      if (words.next(word) && word == "TextureFile" && words.next(file) &&
          header.texture_files.size() < kMaxMeshTextures) {
        header.texture_files.emplace_back(file);
      }
    } else if (keyword != "obj_info" && !keyword.empty()) {
      failure.what = "unexpected header line " + text::quoted(line) +
                     (format_seen ? "" : " (the format line must come first)");
      return false;
    }
    if (!ok) {
      return false;
    }
  }
  failure = {0, "truncated header: no end_header"};
  return false;
}

}  // namespace gfield
