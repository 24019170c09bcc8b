#pragma once
// What the OpenEXR files of geometry images and geometry fields share (internal to gfield_core:
// exr_*.cpp): the gfield header attributes, frame buffers over interleaved arrays, atomic writes
// of scanlines, checked reads.

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gfield/box.hpp"
#include "gfield/exr_io.hpp"

namespace gfield::exr {

inline constexpr const char* kImageTag = "geometry-image";
inline constexpr const char* kFieldTag = "geometry-field";
inline constexpr int kMinSamplesPerSide = 1;
inline constexpr int kMaxSamplesPerSide = 64;
inline constexpr int kMaxFieldSide = 6 * kMaxSamplesPerSide * kMaxSamplesPerSide;

/// Sizes OpenEXR's thread pool to the cores once, unless the application sized it.
void use_all_cores();

Imf::PixelType pixel_type(ExrPrecision precision);

/// A header with the gfield attributes (format tag, version, box, source, build id).
Imf::Header make_header(int width, int height, const char* tag, int version, const Box& box,
                        const std::string& source, const std::string& build_id);

/// A float slice over an interleaved array of `components` floats per pixel.
Imf::Slice float_slice(const float* base, int components, int width);

/// Frame buffer for writing: OpenEXR converts pixel types when reading but not when writing, so
/// HALF channels get a converted copy (kept alive in `halves` until the write is done). Slices
/// start at scanline `first_row` of the data window.
struct OutputChannels {
  Imf::FrameBuffer frame_buffer;
  std::vector<std::vector<half>> halves;
  int first_row = 0;

  void add(Imf::Header& header, const char* name, Imf::PixelType type, const float* base,
           int components, size_t count, int width) {
    header.channels().insert(name, Imf::Channel(type));
    add_slice(name, type, base, components, count, width);
  }
  /// A slice of a channel the header already has.
  void add_slice(const char* name, Imf::PixelType type, const float* base, int components,
                 size_t count, int width) {
    const ptrdiff_t origin = ptrdiff_t(first_row) * width;
    if (type == Imf::FLOAT) {
      frame_buffer.insert(name, float_slice(base - origin * components, components, width));
      return;
    }
    std::vector<half>& h = halves.emplace_back(count);
    for (size_t i = 0; i < count; ++i) {
      h[i] = half(base[i * size_t(components)]);
    }
    frame_buffer.insert(name, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(h.data() - origin),
                                         sizeof(half), sizeof(half) * size_t(width)));
  }
};

/// Scanlines written from one frame buffer: `rows` of them, after those of the parts before.
struct RowsFrom {
  const Imf::FrameBuffer* frame_buffer;
  int rows;
};

/// Writes the scanlines of `parts` in order to `filename` through a temporary file renamed
/// over it. False with an error "FILE: cannot write OpenEXR file (...)".
bool write_exr(const std::string& filename, const Imf::Header& header,
               std::initializer_list<RowsFrom> parts, std::string& error);

/// The same for one frame buffer of `height` rows.
bool write_exr(const std::string& filename, const Imf::Header& header,
               const Imf::FrameBuffer& frame_buffer, int height, std::string& error);

/// "(x, y, z)" for messages.
std::string vec_text(glm::vec3 v);

/// Reads and checks the gfield header attributes.
bool read_header(const std::string& filename, const Imf::Header& h, ExrAssetHeader& out,
                 std::string& error);

/// The format tag is `tag` and the version within [oldest_version, newest_version].
bool check_format(const std::string& filename, const ExrAssetHeader& header, const char* tag,
                  int oldest_version, int newest_version, std::string& error);

/// Each of `names` is a channel of `h`.
bool check_channels(const std::string& filename, const Imf::Header& h,
                    std::initializer_list<const char*> names, std::string& error);

/// open_exr_input (exr_input.hpp) with OpenEXR's threads in use and a square size bound.
bool open_input(const std::string& filename, int max_side,
                std::initializer_list<const char*> channels, std::unique_ptr<Imf::InputFile>& file,
                std::string& error);

/// Reads scanlines first..last (data-window coordinates) into `frame_buffer`.
bool read_rows(const std::string& filename, Imf::InputFile& file,
               const Imf::FrameBuffer& frame_buffer, int first, int last, std::string& error);

/// Reads the whole data window into `frame_buffer`.
bool read_pixels(const std::string& filename, Imf::InputFile& file,
                 const Imf::FrameBuffer& frame_buffer, std::string& error);

}  // namespace gfield::exr
