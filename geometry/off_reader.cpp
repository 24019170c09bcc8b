// OFF (Geomview): a header [ST][C][N]OFF [BINARY], the counts "V F [E]", V vertex lines (x y z,
// then optional normal, colour or texture coordinates, ignored) and F face lines (n, n indices,
// then an optional colour, ignored); '#' starts a comment. Binary OFF: big-endian int32 counts,
// V * 3 float32, per face int32 n, n int32 indices, int32 k and k float32 (its colour); the
// binary form is read for plain "OFF BINARY" only.

#include <bit>
#include <cstring>
#include <vector>

#include "geometry/mesh_readers.hpp"
#include "geometry/text_scan.hpp"
#include "gfield/limits.hpp"

namespace gfield {
namespace {

/// Fewest bytes a vertex and a face take in a text OFF ("0 0 0\n", "3 0 1 2\n").
constexpr std::uint64_t kMinTextVertexBytes = 6;
constexpr std::uint64_t kMinTextFaceBytes = 8;

/// The next line with its comment removed that holds a word; false at the end of the data.
bool next_content_line(text::Lines& lines, std::string_view& line) {
  while (lines.next(line)) {
    line = line.substr(0, line.find('#'));
    if (!text::Words(line).empty()) {
      return true;
    }
  }
  return false;
}

struct OffHeader {
  bool binary = false;
  std::string_view rest;  ///< what follows the keyword on its line (counts, or BINARY)
};

/// "[ST][C][N]OFF" (4OFF and nOFF, other dimensions, are not supported).
bool read_keyword(std::string_view line, OffHeader& header, std::string& what) {
  text::Words words(line);
  std::string_view keyword;
  words.next(keyword);
  std::string_view prefix = keyword;
  if (prefix.size() < 3 || prefix.substr(prefix.size() - 3) != "OFF") {
    what = "not an OFF file (the first line is " + text::quoted(keyword) + ", expected OFF)";
    return false;
  }
  prefix.remove_suffix(3);
  for (const std::string_view part : {"ST", "C", "N"}) {
    if (prefix.substr(0, part.size()) == part) {
      prefix.remove_prefix(part.size());
    }
  }
  if (!prefix.empty()) {
    what = "unsupported OFF variant " + text::quoted(keyword) + " (3D [ST][C][N]OFF only)";
    return false;
  }
  header.rest = line.substr(size_t(keyword.data() + keyword.size() - line.data()));
  text::Words rest(header.rest);
  std::string_view word;
  if (rest.next(word) && word == "BINARY") {
    if (keyword != "OFF") {
      what = "binary " + text::quoted(keyword) + " is not supported (binary OFF only)";
      return false;
    }
    header.binary = true;
  }
  return true;
}

/// The counts "V F [E]" from `line`.
bool read_counts(std::string_view line, std::int64_t& vertices, std::int64_t& faces,
                 std::string& what) {
  text::Words words(line);
  std::string_view v, f, e;
  std::int64_t edges = 0;
  if (!words.next(v) || !words.next(f) || !text::parse_int64(v, vertices) ||
      !text::parse_int64(f, faces) || (words.next(e) && !text::parse_int64(e, edges)) ||
      !words.empty()) {
    what = "malformed counts line (expected \"VERTICES FACES EDGES\")";
    return false;
  }
  return true;
}

bool read_text_vertices(text::Lines& lines, std::int64_t count, MeshSoup& soup,
                        ReadFailure& failure) {
  std::string_view line;
  for (std::int64_t i = 0; i < count; ++i) {
    if (!next_content_line(lines, line)) {
      failure = {0,
                 "truncated: " + std::to_string(i) + " of " + std::to_string(count) + " vertices"};
      return false;
    }
    failure.line = lines.number();
    text::Words words(line);
    double xyz[3];
    for (double& v : xyz) {
      std::string_view word;
      if (!words.next(word)) {
        failure.what = "a vertex needs 3 coordinates";
        return false;
      }
      if (!text::parse_double(word, v)) {
        failure.what = "vertex coordinate " + text::quoted(word) + " is not a number";
        return false;
      }
    }
    if (!add_vertex(soup, xyz[0], xyz[1], xyz[2], failure.what)) {
      return false;
    }
  }
  return true;
}

bool read_text_faces(text::Lines& lines, std::int64_t count, std::int64_t vertices, MeshSoup& soup,
                     ReadFailure& failure) {
  std::string_view line;
  std::vector<std::int64_t> corners;
  for (std::int64_t i = 0; i < count; ++i) {
    if (!next_content_line(lines, line)) {
      failure = {0, "truncated: " + std::to_string(i) + " of " + std::to_string(count) + " faces"};
      return false;
    }
    failure.line = lines.number();
    text::Words words(line);
    std::string_view word;
    std::int64_t n = 0;
    words.next(word);
    if (!text::parse_int64(word, n) || n < 3 || n > kMaxPolygonCorners) {
      failure.what = "face corner count " + text::quoted(word) + " is not an integer in [3, " +
                     std::to_string(kMaxPolygonCorners) + "]";
      return false;
    }
    corners.clear();
    for (std::int64_t k = 0; k < n; ++k) {
      std::int64_t index = 0;
      if (!words.next(word)) {
        failure.what =
            "short face: " + std::to_string(k) + " of its " + std::to_string(n) + " corners";
        return false;
      }
      if (!text::parse_int64(word, index)) {
        failure.what = "face index " + text::quoted(word) + " is not an integer";
        return false;
      }
      if (!check_index(index, vertices, failure.what)) {
        return false;
      }
      corners.push_back(index);
    }
    if (!add_polygon(soup, corners, failure.what)) {
      return false;
    }
  }
  return true;
}

/// Big-endian 32-bit words of binary OFF, bounds-checked.
class BigEndianWords {
 public:
  explicit BigEndianWords(std::string_view data) : data_(data) {}
  bool next(std::uint32_t& word) {
    if (data_.size() - position_ < 4) {
      return false;
    }
    std::uint32_t raw;
    std::memcpy(&raw, data_.data() + position_, 4);
    position_ += 4;
    word = std::endian::native == std::endian::little ? __builtin_bswap32(raw) : raw;
    return true;
  }
  std::uint64_t remaining() const { return data_.size() - position_; }

 private:
  std::string_view data_;
  size_t position_ = 0;
};

bool read_binary(std::string_view data, MeshSoup& soup, ReadFailure& failure) {
  BigEndianWords words(data);
  std::uint32_t counts[3];
  for (std::uint32_t& c : counts) {
    if (!words.next(c)) {
      failure.what = "truncated binary OFF counts";
      return false;
    }
  }
  const std::int64_t vertices = std::int32_t(counts[0]);
  const std::int64_t faces = std::int32_t(counts[1]);
  if (!check_count(vertices, kMaxMeshVertices, 12, words.remaining(), "vertices", failure.what) ||
      !check_count(faces, kMaxMeshTriangles, 20, words.remaining() - 12 * std::uint64_t(vertices),
                   "faces", failure.what)) {
    return false;
  }
  soup.mesh.positions.reserve(size_t(vertices));
  for (std::int64_t i = 0; i < vertices; ++i) {
    double xyz[3];
    for (double& v : xyz) {
      std::uint32_t bits = 0;
      words.next(bits);  // check_count made sure the bytes are there
      v = double(std::bit_cast<float>(bits));
    }
    if (!add_vertex(soup, xyz[0], xyz[1], xyz[2], failure.what)) {
      failure.what = "vertex " + std::to_string(i) + ": " + failure.what;
      return false;
    }
  }
  std::vector<std::int64_t> corners;
  for (std::int64_t i = 0; i < faces; ++i) {
    std::uint32_t n = 0, word = 0;
    if (!words.next(n) || std::int32_t(n) < 3 || std::int32_t(n) > kMaxPolygonCorners ||
        words.remaining() < 4 * std::uint64_t(n) + 4) {
      failure.what = "face " + std::to_string(i) + ": corner count " +
                     std::to_string(std::int32_t(n)) + " not in [3, " +
                     std::to_string(kMaxPolygonCorners) + "] or beyond the end of the file";
      return false;
    }
    corners.clear();
    for (std::uint32_t k = 0; k < n; ++k) {
      words.next(word);
      corners.push_back(std::int32_t(word));
      if (!check_index(corners.back(), vertices, failure.what)) {
        failure.what = "face " + std::to_string(i) + ": " + failure.what;
        return false;
      }
    }
    std::uint32_t colour = 0;
    words.next(colour);
    if (colour > 4 || words.remaining() < 4 * std::uint64_t(colour)) {
      failure.what = "face " + std::to_string(i) + ": malformed colour";
      return false;
    }
    for (std::uint32_t k = 0; k < colour; ++k) {
      words.next(word);
    }
    if (!add_polygon(soup, corners, failure.what)) {
      return false;
    }
  }
  return true;
}

}  // namespace

bool read_off(std::string_view data, MeshSoup& soup, ReadFailure& failure) {
  text::Lines lines(data);
  std::string_view line;
  OffHeader header;
  if (!next_content_line(lines, line) || !read_keyword(line, header, failure.what)) {
    failure.line = lines.number();
    failure.what = failure.what.empty() ? "not an OFF file (no OFF keyword)" : failure.what;
    return false;
  }
  if (header.binary) {
    const size_t start = data.size() - lines.remaining();
    return read_binary(data.substr(start), soup, failure);
  }
  std::string_view counts = header.rest;
  if (text::Words(counts).empty()) {
    if (!next_content_line(lines, counts)) {
      failure.what = "truncated: no counts line";
      return false;
    }
  }
  failure.line = lines.number();
  std::int64_t vertices = 0, faces = 0;
  const std::uint64_t left = lines.remaining() + 1;
  if (!read_counts(counts, vertices, faces, failure.what) ||
      !check_count(vertices, kMaxMeshVertices, kMinTextVertexBytes, left, "vertices",
                   failure.what) ||
      !check_count(faces, kMaxMeshTriangles, kMinTextFaceBytes,
                   left - kMinTextVertexBytes * std::uint64_t(vertices), "faces", failure.what)) {
    return false;
  }
  soup.mesh.positions.reserve(size_t(vertices));
  return read_text_vertices(lines, vertices, soup, failure) &&
         read_text_faces(lines, faces, vertices, soup, failure);
}

}  // namespace gfield
