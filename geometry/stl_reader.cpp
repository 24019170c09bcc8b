// STL: binary (80-byte header, uint32 triangle count, 50 bytes per triangle, little endian; the
// file size must be exactly 84 + 50 * count) or ASCII ("solid", then "facet normal nx ny nz",
// "outer loop", three "vertex x y z", "endloop", "endfacet" per triangle, "endsolid"; several
// solids may follow each other). Corners at bit-identical positions become one vertex (STL stores
// triangles, not shared vertices); nothing else is merged or dropped.

#include <bit>
#include <cctype>
#include <cstring>
#include <unordered_map>

#include "geometry/mesh_readers.hpp"
#include "geometry/text_scan.hpp"
#include "gfield/limits.hpp"

namespace gfield {
namespace {

/// Welds corners at bit-identical float positions (with -0 == +0).
class Welder {
 public:
  explicit Welder(MeshSoup& soup) : soup_(soup) {}

  bool corner(double x, double y, double z, std::int64_t& index, std::string& what) {
    Key key;
    const float xyz[3] = {float(x) + 0.0f, float(y) + 0.0f, float(z) + 0.0f};
    std::memcpy(key.bits, xyz, sizeof(xyz));
    const auto found = index_.find(key);
    if (found != index_.end()) {
      index = found->second;
      return true;
    }
    if (!add_vertex(soup_, x, y, z, what)) {
      return false;
    }
    index = std::int64_t(soup_.mesh.positions.size()) - 1;
    index_.emplace(key, index);
    return true;
  }

 private:
  struct Key {
    std::uint32_t bits[3];
    bool operator==(const Key& o) const { return std::memcmp(bits, o.bits, sizeof(bits)) == 0; }
  };
  struct Hash {
    size_t operator()(const Key& k) const {
      const std::uint64_t a = (std::uint64_t(k.bits[0]) << 32) | k.bits[1];
      return std::hash<std::uint64_t>()(a * 0x9E3779B97F4A7C15ull ^ k.bits[2]);
    }
  };
  MeshSoup& soup_;
  std::unordered_map<Key, std::int64_t, Hash> index_;
};

bool read_binary(std::string_view data, MeshSoup& soup, ReadFailure& failure) {
  std::uint32_t count = 0;
  std::memcpy(&count, data.data() + 80, 4);
  count = std::endian::native == std::endian::little ? count : __builtin_bswap32(count);
  soup.mesh.positions.reserve(size_t(count) / 2);
  Welder welder(soup);
  std::int64_t corners[3];
  for (std::uint32_t t = 0; t < count; ++t) {
    const char* facet = data.data() + 84 + 50 * size_t(t);
    for (int c = 0; c < 3; ++c) {
      float xyz[3];
      std::memcpy(xyz, facet + 12 * (c + 1), sizeof(xyz));
      if (!welder.corner(xyz[0], xyz[1], xyz[2], corners[c], failure.what)) {
        failure.what = "triangle " + std::to_string(t) + ": " + failure.what;
        return false;
      }
    }
    if (!add_polygon(soup, corners, failure.what)) {
      return false;
    }
  }
  return true;
}

/// True when `word` is `keyword` (lower case), compared case-insensitively.
bool keyword_is(std::string_view word, std::string_view keyword) {
  bool same = word.size() == keyword.size();
  for (size_t i = 0; same && i < word.size(); ++i) {
    same = std::tolower(static_cast<unsigned char>(word[i])) == keyword[i];
  }
  return same;
}

/// The next word, which must be `keyword`.
bool expect(text::WordStream& words, std::string_view keyword, ReadFailure& failure) {
  std::string_view word;
  const bool found = words.next(word);
  failure.line = words.line();
  if (!keyword_is(word, keyword)) {
    failure.what = found ? "expected '" + std::string(keyword) + "', found " + text::quoted(word)
                         : "truncated: expected '" + std::string(keyword) + "'";
    return false;
  }
  return true;
}

bool read_numbers(text::WordStream& words, double* values, ReadFailure& failure) {
  for (int k = 0; k < 3; ++k) {
    std::string_view word;
    if (!words.next(word) || !text::parse_double(word, values[k])) {
      failure.line = words.line();
      failure.what = word.empty() ? "truncated facet" : text::quoted(word) + " is not a number";
      return false;
    }
  }
  return true;
}

bool read_facet(text::WordStream& words, Welder& welder, MeshSoup& soup, ReadFailure& failure) {
  double values[3];
  std::int64_t corners[3];
  if (!expect(words, "normal", failure) || !read_numbers(words, values, failure) ||
      !expect(words, "outer", failure) || !expect(words, "loop", failure)) {
    return false;
  }
  for (int c = 0; c < 3; ++c) {
    std::string_view word;
    words.next(word);
    failure.line = words.line();
    if (!keyword_is(word, "vertex")) {
      failure.what = keyword_is(word, "endloop")
                         ? "a facet with " + std::to_string(c) + " vertices (3 needed)"
                         : "expected 'vertex', found " + text::quoted(word);
      return false;
    }
    if (!read_numbers(words, values, failure) ||
        !welder.corner(values[0], values[1], values[2], corners[c], failure.what)) {
      return false;
    }
  }
  if (!expect(words, "endloop", failure)) {
    failure.what = "a facet with more than 3 vertices, or " + failure.what;
    return false;
  }
  return expect(words, "endfacet", failure) && add_polygon(soup, corners, failure.what);
}

bool read_ascii(std::string_view data, MeshSoup& soup, ReadFailure& failure) {
  text::WordStream words(data);
  Welder welder(soup);
  if (!expect(words, "solid", failure)) {
    return false;
  }
  words.skip_line();  // the solid's name
  std::string_view word;
  while (words.next(word)) {
    failure.line = words.line();
    if (keyword_is(word, "facet")) {
      if (!read_facet(words, welder, soup, failure)) {
        return false;
      }
    } else if (keyword_is(word, "endsolid")) {
      words.skip_line();
      if (!words.next(word)) {
        failure.line = 0;
        return true;
      }
      failure.line = words.line();
      if (!keyword_is(word, "solid")) {
        failure.what = "expected 'solid' after 'endsolid', found " + text::quoted(word);
        return false;
      }
      words.skip_line();
    } else {
      failure.what = "expected 'facet' or 'endsolid', found " + text::quoted(word);
      return false;
    }
  }
  failure.what = "truncated: no 'endsolid'";
  return false;
}

}  // namespace

bool read_stl(std::string_view data, MeshSoup& soup, ReadFailure& failure) {
  const bool text_start = data.substr(0, 5) == "solid";
  if (data.size() >= 84) {
    std::uint32_t count = 0;
    std::memcpy(&count, data.data() + 80, 4);
    count = std::endian::native == std::endian::little ? count : __builtin_bswap32(count);
    const std::uint64_t expected = 84 + 50 * std::uint64_t(count);
    if (expected == data.size()) {
      return read_binary(data, soup, failure);
    }
    if (!text_start) {
      failure.what = "binary STL of " + std::to_string(count) + " triangles needs " +
                     std::to_string(expected) + " bytes, the file has " +
                     std::to_string(data.size()) + " (truncated or not an STL file)";
      return false;
    }
  }
  if (!text_start) {
    failure.what = "not an STL file (no 'solid' at the start, too short for binary STL)";
    return false;
  }
  return read_ascii(data, soup, failure);
}

}  // namespace gfield
