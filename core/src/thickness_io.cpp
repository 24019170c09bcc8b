#include "gfield/thickness.hpp"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfVecAttribute.h>

#include <exception>
#include <memory>

#include "exr_input.hpp"
#include "gfield/atomic_file.hpp"
#include "gfield/exr_io.hpp"
#include "gfield/limits.hpp"

namespace gfield {

namespace {
constexpr const char* kThicknessTag = "thickness";
constexpr const char* kSuffix = ".gimage.exr";
}  // namespace

std::string thickness_path(const std::string& geometry_image_path) {
  const std::string suffix(kSuffix);
  if (geometry_image_path.size() > suffix.size() &&
      geometry_image_path.compare(geometry_image_path.size() - suffix.size(), suffix.size(),
                                  suffix) == 0)
    return geometry_image_path.substr(0, geometry_image_path.size() - suffix.size()) +
           ".thickness.exr";
  return geometry_image_path + ".thickness.exr";
}

bool save_thickness_map(const std::string& filename, const ThicknessMap& map, std::string& error) {
  const int n = map.size;
  if (n <= 0 || map.distance.size() != size_t(n) * size_t(n)) {
    error = filename + ": thickness map of " + std::to_string(map.distance.size()) +
            " values is not " + std::to_string(n) + "^2";
    return false;
  }
  Imf::Header header(n, n);
  header.compression() = Imf::ZIP_COMPRESSION;
  header.insert("gfield.format", Imf::StringAttribute(kThicknessTag));
  header.insert("gfield.version", Imf::IntAttribute(kFormatVersion));
  header.insert("gfield.boxMin", Imf::V3fAttribute({map.box.min.x, map.box.min.y, map.box.min.z}));
  header.insert("gfield.boxMax", Imf::V3fAttribute({map.box.max.x, map.box.max.y, map.box.max.z}));
  header.insert("gfield.source", Imf::StringAttribute(map.source));
  header.channels().insert("D", Imf::Channel(Imf::FLOAT));
  Imf::FrameBuffer frame;
  frame.insert(
      "D", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(map.distance.data())),
                      sizeof(float), sizeof(float) * size_t(n)));
  TemporaryFile tmp(filename);
  try {
    Imf::OutputFile file(tmp.path().c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(n);
  } catch (const std::exception& e) {
    error = filename + ": cannot write OpenEXR file (" + tmp.as_target(e.what()) + ")";
    return false;
  }
  return tmp.commit(error);
}

namespace {

/// The header's tag, version, size, box and source; false with "FILE: problem".
bool read_thickness_header(const std::string& filename, const Imf::Header& header,
                           ThicknessMap& map, std::string& error) {
  const auto* tag = header.findTypedAttribute<Imf::StringAttribute>("gfield.format");
  if (tag == nullptr || tag->value() != kThicknessTag) {
    error = filename + ": not a thickness map (gfield.format is not \"thickness\")";
    return false;
  }
  const auto* version = header.findTypedAttribute<Imf::IntAttribute>("gfield.version");
  if (version == nullptr || version->value() != kFormatVersion) {
    error = filename + ": unsupported gfield.version";
    return false;
  }
  const Imath::Box2i window = header.dataWindow();
  const int width = window.max.x - window.min.x + 1;
  const int height = window.max.y - window.min.y + 1;
  if (width != height) {
    error = filename + ": thickness map is " + std::to_string(width) + "x" +
            std::to_string(height) + ", not square";
    return false;
  }
  if (header.channels().findChannel("D") == nullptr) {
    error = filename + ": no channel D";
    return false;
  }
  map.size = width;
  if (const auto* lo = header.findTypedAttribute<Imf::V3fAttribute>("gfield.boxMin"))
    map.box.min = {lo->value().x, lo->value().y, lo->value().z};
  if (const auto* hi = header.findTypedAttribute<Imf::V3fAttribute>("gfield.boxMax"))
    map.box.max = {hi->value().x, hi->value().y, hi->value().z};
  if (const auto* source = header.findTypedAttribute<Imf::StringAttribute>("gfield.source"))
    map.source = source->value();
  const glm::vec3 limit(static_cast<float>(kMaxAssetCoordinate));
  if (!glm::all(glm::lessThanEqual(glm::abs(map.box.min), limit)) ||
      !glm::all(glm::lessThanEqual(glm::abs(map.box.max), limit))) {
    error = filename + ": gfield.boxMin/boxMax not finite or beyond +-1e16";
    return false;
  }
  return true;
}

}  // namespace

bool load_thickness_map(const std::string& filename, ThicknessMap& map, std::string& error) {
  std::unique_ptr<Imf::InputFile> file;
  if (!open_exr_input(filename, kMaxGeometryImageSide, kMaxGeometryImageSide, {"D"}, file, error))
    return false;
  ThicknessMap out;
  try {
    const Imf::Header& header = file->header();
    if (!read_thickness_header(filename, header, out, error))
      return false;
    const Imath::Box2i window = header.dataWindow();
    const int width = out.size;
    out.distance.assign(size_t(width) * size_t(width), 0.0f);
    Imf::FrameBuffer frame;
    char* base =
        reinterpret_cast<char*>(out.distance.data()) -
        (std::ptrdiff_t(window.min.y) * width + window.min.x) * std::ptrdiff_t(sizeof(float));
    frame.insert("D", Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * size_t(width)));
    file->setFrameBuffer(frame);
    file->readPixels(window.min.y, window.max.y);
  } catch (const std::exception& e) {
    error = filename + ": cannot read OpenEXR file (" + exr_exception_text(e) + ")";
    return false;
  }
  for (size_t t = 0; t < out.distance.size(); ++t) {
    if (!(out.distance[t] >= 0.0f && out.distance[t] <= float(kMaxAssetDistance))) {
      error = filename + ": distance " + std::to_string(out.distance[t]) + " at texel " +
              std::to_string(t) + " is not in [0, 1e17]";
      return false;
    }
  }
  map = std::move(out);
  return true;
}

}  // namespace gfield
