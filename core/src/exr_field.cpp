// Geometry fields as OpenEXR files, format version 3, the compact field (docs/formats.md): the
// nearest-hit table, the line table and the interior hits; older versions read through
// exr_layered_field.

#include <OpenEXR/ImfIntAttribute.h>

#include <algorithm>

#include "exr_common.hpp"
#include "exr_input.hpp"
#include "exr_layered_field.hpp"
#include "gfield/exr_io.hpp"
#include "gfield/field_lines.hpp"
#include "gfield/limits.hpp"

namespace gfield {
namespace {

using namespace exr;

// A compact field's channels and attributes (docs/formats.md).
constexpr const char* kHitU = "hit.U";
constexpr const char* kHitV = "hit.V";
constexpr const char* kLineChannel = "line";
constexpr const char* kLineWordsAttribute = "gfield.lineWords";
constexpr const char* kInteriorHitsAttribute = "gfield.interiorHits";

// The channels of a compact field: hit.U and hit.V, both HALF or both FLOAT, and line, UINT.
bool check_compact_channels(const std::string& filename, const Imf::Header& h, std::string& error) {
  const Imf::Channel* u = h.channels().findChannel(kHitU);
  const Imf::Channel* v = h.channels().findChannel(kHitV);
  const Imf::Channel* line = h.channels().findChannel(kLineChannel);
  size_t count = 0;
  for (auto c = h.channels().begin(); c != h.channels().end(); ++c) {
    ++count;
  }
  if (u == nullptr || v == nullptr || line == nullptr || count != 3) {
    error = filename +
            ": a version-3 geometry field holds the channels hit.U, hit.V and line, "
            "and no others";
    return false;
  }
  if (u->type != v->type || (u->type != Imf::HALF && u->type != Imf::FLOAT) ||
      line->type != Imf::UINT) {
    error = filename + ": hit.U and hit.V must be both HALF or both FLOAT, line UINT";
    return false;
  }
  return true;
}

// The size of a compact field: N in range, 5N^2 columns, and 6N^2 rows of nearest hits followed
// by as many rows as its line words and interior hits (attributes) need.
bool check_compact_size(const std::string& filename, const Imf::Header& h,
                        const ExrAssetHeader& header, size_t& words, size_t& hits,
                        std::string& error) {
  const int n = header.samples_per_side;
  const auto* word_count = h.findTypedAttribute<Imf::IntAttribute>(kLineWordsAttribute);
  const auto* hit_count = h.findTypedAttribute<Imf::IntAttribute>(kInteriorHitsAttribute);
  if (n < kMinSamplesPerSide || n > kMaxSamplesPerSide || header.layers < 1 ||
      header.layers > kMaxLineHits || word_count == nullptr || hit_count == nullptr ||
      word_count->value() < 0 || hit_count->value() < 0) {
    error = filename + ": gfield.samplesPerSide, gfield.layers (1 to " +
            std::to_string(kMaxLineHits) + "), " + kLineWordsAttribute + " or " +
            kInteriorHitsAttribute + " missing or out of range";
    return false;
  }
  words = size_t(word_count->value());
  hits = size_t(hit_count->value());
  const size_t width = size_t(5 * n * n);
  const size_t rows = size_t(sample_count(n)) + (std::max(words, hits) + width - 1) / width;
  if (size_t(header.width) != width || size_t(header.height) != rows) {
    error = filename + ": geometry field is " + std::to_string(header.width) + "x" +
            std::to_string(header.height) + ", expected " + std::to_string(width) + "x" +
            std::to_string(rows) + " for N = " + std::to_string(n) + ", " + std::to_string(words) +
            " line words and " + std::to_string(hits) + " interior hits";
    return false;
  }
  return true;
}

/// A compact field's tables (version 3) from an open file whose header was checked.
bool read_compact_tables(const std::string& filename, Imf::InputFile& file,
                         const ExrAssetHeader& header, GeometryField& out, std::string& error) {
  size_t words = 0, hits = 0;
  if (!check_compact_channels(filename, file.header(), error) ||
      !check_compact_size(filename, file.header(), header, words, hits, error)) {
    return false;
  }
  const int width = field_columns(out);
  const int rows = field_side(out);
  const int extra_rows = header.height - rows;
  out.nearest.resize(field_nearest_size(out));
  const Imath::Box2i dw = file.header().dataWindow();
  Imf::FrameBuffer nearest;
  float* uv = &out.nearest[0].x - (ptrdiff_t(dw.min.y) * width + dw.min.x) * 2;
  nearest.insert(kHitU, float_slice(uv + 0, 2, width));
  nearest.insert(kHitV, float_slice(uv + 1, 2, width));
  if (!read_rows(filename, file, nearest, dw.min.y, dw.min.y + rows - 1, error)) {
    return false;
  }
  if (extra_rows > 0) {
    const size_t padded = size_t(extra_rows) * size_t(width);
    std::vector<glm::vec2> interior(padded);
    std::vector<uint32_t> lines(padded);
    const ptrdiff_t origin = ptrdiff_t(dw.min.y + rows) * width + dw.min.x;
    Imf::FrameBuffer tables;
    tables.insert(kHitU, float_slice(&interior[0].x - origin * 2, 2, width));
    tables.insert(kHitV, float_slice(&interior[0].x - origin * 2 + 1, 2, width));
    tables.insert(kLineChannel,
                  Imf::Slice(Imf::UINT, reinterpret_cast<char*>(lines.data() - origin),
                             sizeof(uint32_t), sizeof(uint32_t) * size_t(width)));
    if (!read_rows(filename, file, tables, dw.min.y + rows, dw.max.y, error)) {
      return false;
    }
    out.interior.assign(interior.begin(), interior.begin() + ptrdiff_t(hits));
    out.lines.assign(lines.begin(), lines.begin() + ptrdiff_t(words));
  }
  std::string why;
  if (!check_field_tables(out, why)) {
    error = filename + ": " + why;
    return false;
  }
  return true;
}

}  // namespace

bool save_geometry_field(const std::string& filename, const GeometryField& field,
                         ExrPrecision precision, std::string& error) {
  const int n = field.samples_per_side;
  if (n < kMinSamplesPerSide || n > kMaxSamplesPerSide || field.layers < 1 ||
      field.layers > kMaxLineHits || field.nearest.size() != field_nearest_size(field)) {
    error = filename + ": geometry field tables do not match N = " + std::to_string(n) +
            " or layers " + std::to_string(field.layers) + " out of range";
    return false;
  }
  const int width = field_columns(field);
  const int rows = field_side(field);
  const size_t extra = std::max(field.lines.size(), field.interior.size());
  const int extra_rows = int((extra + size_t(width) - 1) / size_t(width));
  Imf::Header header = make_header(width, rows + extra_rows, kFieldTag, kFieldFormatVersion,
                                   field.box, field.source, field.build_id);
  header.insert("gfield.samplesPerSide", Imf::IntAttribute(n));
  header.insert("gfield.layers", Imf::IntAttribute(field.layers));
  header.insert(kLineWordsAttribute, Imf::IntAttribute(int(field.lines.size())));
  header.insert(kInteriorHitsAttribute, Imf::IntAttribute(int(field.interior.size())));
  header.zipCompressionLevel() = 1;  // docs/geometry-field.md: fast, a few % larger
  // Rows 0..6N^2-1: the nearest hits (line: 0); then the interior hits and the line words.
  OutputChannels nearest;
  const float* uv = &field.nearest[0].x;
  nearest.add(header, kHitU, pixel_type(precision), uv, 2, field.nearest.size(), width);
  nearest.add(header, kHitV, pixel_type(precision), uv + 1, 2, field.nearest.size(), width);
  header.channels().insert(kLineChannel, Imf::Channel(Imf::UINT));
  const std::vector<uint32_t> zero_row(size_t(width), 0u);
  nearest.frame_buffer.insert(
      kLineChannel,
      Imf::Slice(Imf::UINT, reinterpret_cast<char*>(const_cast<uint32_t*>(zero_row.data())),
                 sizeof(uint32_t), 0));
  const size_t padded = size_t(extra_rows) * size_t(width);
  std::vector<glm::vec2> interior(padded, glm::vec2(0.0f));
  std::copy(field.interior.begin(), field.interior.end(), interior.begin());
  std::vector<uint32_t> lines(padded, 0u);
  std::copy(field.lines.begin(), field.lines.end(), lines.begin());
  OutputChannels tables;
  tables.first_row = rows;
  if (padded > 0) {
    const float* hits = &interior[0].x;
    tables.add_slice(kHitU, pixel_type(precision), hits, 2, padded, width);
    tables.add_slice(kHitV, pixel_type(precision), hits + 1, 2, padded, width);
    const ptrdiff_t origin = ptrdiff_t(rows) * width;
    tables.frame_buffer.insert(kLineChannel,
                               Imf::Slice(Imf::UINT, reinterpret_cast<char*>(lines.data() - origin),
                                          sizeof(uint32_t), sizeof(uint32_t) * size_t(width)));
  }
  return write_exr(
      filename, header,
      {RowsFrom{&nearest.frame_buffer, rows}, RowsFrom{&tables.frame_buffer, extra_rows}}, error);
}

bool load_geometry_field(const std::string& filename, GeometryField& field, std::string& error) {
  std::unique_ptr<Imf::InputFile> file;
  use_all_cores();
  // The rows of a compact field's line table below its 6N^2 rows: at most as many again.
  if (!open_exr_input(filename, kMaxFieldSide, 2 * kMaxFieldSide, {}, file, error)) {
    return false;  // channels: check_field_channels, check_compact_channels
  }
  ExrAssetHeader header;
  if (!read_header(filename, file->header(), header, error) ||
      !check_format(filename, header, kFieldTag, 1, kFieldFormatVersion, error)) {
    return false;
  }
  GeometryField out;
  out.samples_per_side = header.samples_per_side;
  out.layers = header.layers;
  out.box = header.box;
  out.source = header.source;
  out.build_id = header.build_id;
  if (header.version == kFieldFormatVersion) {
    if (!read_compact_tables(filename, *file, header, out, error)) {
      return false;
    }
  } else {
    std::vector<glm::vec2> table;
    if (!read_layered_table(filename, *file, header, table, error)) {
      return false;
    }
    compact_layered_table(table, header.layers, out);
  }
  field = std::move(out);
  return true;
}

}  // namespace gfield
