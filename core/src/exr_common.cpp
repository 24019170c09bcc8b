// The shared parts of the geometry image's and field's OpenEXR files (exr_common.hpp), and
// load_asset_header.

#include "exr_common.hpp"

#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>
#include <OpenEXR/ImfVecAttribute.h>
#include <glm/gtx/compatibility.hpp>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <mutex>
#include <thread>

#include "exr_input.hpp"
#include "gfield/atomic_file.hpp"
#include "gfield/build_id.hpp"
#include "gfield/limits.hpp"
#include "gfield/printable.hpp"

namespace gfield {
namespace exr {
namespace {

Imath::V3f to_imath(glm::vec3 v) {
  return {v.x, v.y, v.z};
}
glm::vec3 to_glm(const Imath::V3f& v) {
  return {v.x, v.y, v.z};
}

}  // namespace

void use_all_cores() {
  static std::once_flag once;
  // An application that sized OpenEXR's pool itself (gfield --threads) keeps its size.
  std::call_once(once, [] {
    if (Imf::globalThreadCount() == 0) {
      Imf::setGlobalThreadCount(int(std::thread::hardware_concurrency()));
    }
  });
}

Imf::PixelType pixel_type(ExrPrecision precision) {
  return precision == ExrPrecision::kHalf ? Imf::HALF : Imf::FLOAT;
}

Imf::Header make_header(int width, int height, const char* tag, int version, const Box& box,
                        const std::string& source, const std::string& build_id) {
  Imf::Header header(width, height);
  header.compression() = Imf::ZIP_COMPRESSION;
  header.insert("gfield.format", Imf::StringAttribute(tag));
  header.insert("gfield.version", Imf::IntAttribute(version));
  header.insert("gfield.boxMin", Imf::V3fAttribute(to_imath(box.min)));
  header.insert("gfield.boxMax", Imf::V3fAttribute(to_imath(box.max)));
  header.insert("gfield.source", Imf::StringAttribute(source));
  if (!build_id.empty()) {
    header.insert(kBuildIdAttribute, Imf::StringAttribute(build_id));
  }
  return header;
}

// A float slice over an interleaved array of `components` floats per pixel.
Imf::Slice float_slice(const float* base, int components, int width) {
  const size_t x_stride = sizeof(float) * size_t(components);
  return Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(base)), x_stride,
                    x_stride * size_t(width));
}

bool write_exr(const std::string& filename, const Imf::Header& header,
               std::initializer_list<RowsFrom> parts, std::string& error) {
  use_all_cores();
  TemporaryFile tmp(filename);
  try {
    Imf::OutputFile file(tmp.path().c_str(), header);
    for (const RowsFrom& part : parts) {
      if (part.rows > 0) {
        file.setFrameBuffer(*part.frame_buffer);
        file.writePixels(part.rows);
      }
    }
  } catch (const std::exception& e) {
    error = filename + ": cannot write OpenEXR file (" + tmp.as_target(e.what()) + ")";
    return false;
  }
  return tmp.commit(error);
}

bool write_exr(const std::string& filename, const Imf::Header& header,
               const Imf::FrameBuffer& frame_buffer, int height, std::string& error) {
  return write_exr(filename, header, {RowsFrom{&frame_buffer, height}}, error);
}

/// "(x, y, z)" for messages.
std::string vec_text(glm::vec3 v) {
  char text[96];
  std::snprintf(text, sizeof(text), "(%g, %g, %g)", v.x, v.y, v.z);
  return text;
}

// Reads and checks the gfield header attributes.
bool read_header(const std::string& filename, const Imf::Header& h, ExrAssetHeader& out,
                 std::string& error) {
  const auto* format = h.findTypedAttribute<Imf::StringAttribute>("gfield.format");
  if (!format) {
    error = filename + ": not a gfield asset (no gfield.format attribute)";
    return false;
  }
  out.format = format->value();
  const auto* version = h.findTypedAttribute<Imf::IntAttribute>("gfield.version");
  if (!version) {
    error = filename + ": missing gfield.version attribute";
    return false;
  }
  out.version = version->value();
  const auto* box_min = h.findTypedAttribute<Imf::V3fAttribute>("gfield.boxMin");
  const auto* box_max = h.findTypedAttribute<Imf::V3fAttribute>("gfield.boxMax");
  if (!box_min || !box_max) {
    error = filename + ": missing gfield.boxMin/gfield.boxMax attribute";
    return false;
  }
  out.box = {to_glm(box_min->value()), to_glm(box_max->value())};
  const float limit = float(kMaxAssetCoordinate);
  if (!glm::all(glm::isfinite(out.box.min)) || !glm::all(glm::isfinite(out.box.max)) ||
      !glm::all(glm::lessThan(out.box.min, out.box.max)) ||
      glm::any(glm::greaterThan(glm::abs(out.box.min), glm::vec3(limit))) ||
      glm::any(glm::greaterThan(glm::abs(out.box.max), glm::vec3(limit)))) {
    error = filename + ": invalid box " + vec_text(out.box.min) + " - " + vec_text(out.box.max) +
            " (gfield.boxMin must be below gfield.boxMax, both finite and within +-1e16)";
    return false;
  }
  const auto* source = h.findTypedAttribute<Imf::StringAttribute>("gfield.source");
  out.source = source ? source->value() : std::string();
  const auto* build_id = h.findTypedAttribute<Imf::StringAttribute>(kBuildIdAttribute);
  out.build_id = build_id ? build_id->value() : std::string();
  const auto* samples = h.findTypedAttribute<Imf::IntAttribute>("gfield.samplesPerSide");
  out.samples_per_side = samples ? samples->value() : 0;
  const auto* layers = h.findTypedAttribute<Imf::IntAttribute>("gfield.layers");
  out.layers = layers ? layers->value() : (out.format == kFieldTag && out.version == 1 ? 1 : 0);
  const Imath::Box2i dw = h.dataWindow();
  out.width = dw.max.x - dw.min.x + 1;
  out.height = dw.max.y - dw.min.y + 1;
  return true;
}

/// The format tag is `tag` and the version within [oldest_version, newest_version].
bool check_format(const std::string& filename, const ExrAssetHeader& header, const char* tag,
                  int oldest_version, int newest_version, std::string& error) {
  if (header.format != tag) {
    error =
        filename + ": wrong format tag '" + printable(header.format) + "' (expected '" + tag + "')";
    return false;
  }
  if (header.version < oldest_version || header.version > newest_version) {
    const std::string versions = oldest_version == newest_version
                                     ? "version " + std::to_string(newest_version)
                                     : "versions " + std::to_string(oldest_version) + " to " +
                                           std::to_string(newest_version);
    error = filename + ": unsupported format version " + std::to_string(header.version) +
            " (this build reads " + versions + ")";
    return false;
  }
  return true;
}

bool check_channels(const std::string& filename, const Imf::Header& h,
                    std::initializer_list<const char*> names, std::string& error) {
  for (const char* name : names) {
    if (!h.channels().findChannel(name)) {
      error = filename + ": missing channel '" + name + "'";
      return false;
    }
  }
  return true;
}

bool open_input(const std::string& filename, int max_side,
                std::initializer_list<const char*> channels, std::unique_ptr<Imf::InputFile>& file,
                std::string& error) {
  use_all_cores();
  return open_exr_input(filename, max_side, max_side, channels, file, error);
}

/// Reads scanlines first..last (data-window coordinates) into `frame_buffer`.
bool read_rows(const std::string& filename, Imf::InputFile& file,
               const Imf::FrameBuffer& frame_buffer, int first, int last, std::string& error) {
  try {
    file.setFrameBuffer(frame_buffer);
    file.readPixels(first, last);
  } catch (const std::exception& e) {
    error = filename + ": truncated or corrupt pixel data (" + exr_exception_text(e) + ")";
    return false;
  }
  return true;
}

bool read_pixels(const std::string& filename, Imf::InputFile& file,
                 const Imf::FrameBuffer& frame_buffer, std::string& error) {
  const Imath::Box2i dw = file.header().dataWindow();
  return read_rows(filename, file, frame_buffer, dw.min.y, dw.max.y, error);
}

}  // namespace exr

bool load_asset_header(const std::string& filename, ExrAssetHeader& header, std::string& error) {
  std::unique_ptr<Imf::InputFile> file;
  exr::use_all_cores();
  const int side = std::max(exr::kMaxFieldSide, kMaxGeometryImageSide);
  if (!open_exr_input(filename, side, 2 * side, {}, file, error)) {
    return false;
  }
  return exr::read_header(filename, file->header(), header, error);
}

}  // namespace gfield
