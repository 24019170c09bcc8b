// Geometry images as OpenEXR files (docs/formats.md): P, N, A and the albedo, checked on read.

#include <OpenEXR/ImfFloatAttribute.h>

#include <cstdio>

#include "exr_common.hpp"
#include "gfield/exr_io.hpp"
#include "gfield/limits.hpp"

namespace gfield {
namespace {

using namespace exr;

/// A ray offset a geometry image may carry (NaN: no).
bool valid_ray_offset(float ray_offset) {
  return ray_offset >= kMinRayOffset && ray_offset <= kMaxRayOffset;
}

/// The optional gfield.rayOffset of a geometry image (kMinRayOffset when absent).
bool read_ray_offset(const std::string& filename, const Imf::Header& h, float& ray_offset,
                     std::string& error) {
  const auto* attribute = h.findTypedAttribute<Imf::FloatAttribute>("gfield.rayOffset");
  ray_offset = attribute ? attribute->value() : kMinRayOffset;
  if (!valid_ray_offset(ray_offset)) {
    char text[160];
    std::snprintf(text, sizeof(text), ": gfield.rayOffset %g outside [%g, %g] (box diagonals)",
                  double(ray_offset), double(kMinRayOffset), double(kMaxRayOffset));
    error = filename + text;
    return false;
  }
  return true;
}

/// Positions finite and within kMaxAssetCoordinate, normal components within
/// kMaxNormalComponent, coverage in [0, 1], albedo components in [0, kMaxColorComponent].
bool check_texels(const std::string& filename, const GeometryImage& image, std::string& error) {
  const glm::vec3 limit(static_cast<float>(kMaxAssetCoordinate));
  const glm::vec3 normal_limit(static_cast<float>(kMaxNormalComponent));
  const glm::vec3 color_limit(static_cast<float>(kMaxColorComponent));
  for (size_t t = 0; t < image.position.size(); ++t) {
    const float a = image.coverage[t];
    const bool albedo_ok = image.albedo.empty() ||
                           (glm::all(glm::greaterThanEqual(image.albedo[t], glm::vec3(0.0f))) &&
                            glm::all(glm::lessThanEqual(image.albedo[t], color_limit)));
    if (!glm::all(glm::lessThanEqual(glm::abs(image.position[t]), limit)) ||
        !glm::all(glm::lessThanEqual(glm::abs(image.normal[t]), normal_limit)) ||
        !(a >= 0.0f && a <= 1.0f) || !albedo_ok) {
      error = filename + ": texel (" + std::to_string(t % size_t(image.size)) + ", " +
              std::to_string(t / size_t(image.size)) + "): position " +
              vec_text(image.position[t]) + ", normal " + vec_text(image.normal[t]) +
              ", coverage " + std::to_string(a) +
              (image.albedo.empty() ? std::string() : " or albedo " + vec_text(image.albedo[t])) +
              " out of range (positions within +-1e16, normal components within +-2, coverage "
              "in [0,1], albedo in [0,1e6])";
      return false;
    }
  }
  return true;
}

constexpr const char* kAlbedoChannels[3] = {"albedo.R", "albedo.G", "albedo.B"};

/// Whether a geometry image's header holds albedo: all three channels (version 2), or none.
bool albedo_channels(const std::string& filename, const Imf::Header& h, bool& present,
                     std::string& error) {
  int found = 0;
  for (const char* name : kAlbedoChannels) {
    found += h.channels().findChannel(name) != nullptr;
  }
  present = found == 3;
  if (found != 0 && found != 3) {
    error = filename + ": albedo needs all three channels albedo.R, albedo.G, albedo.B";
    return false;
  }
  return true;
}

}  // namespace

bool save_geometry_image(const std::string& filename, const GeometryImage& image,
                         ExrPrecision precision, std::string& error) {
  const size_t texels = size_t(image.size) * size_t(image.size);
  if (image.size <= 0 || image.position.size() != texels || image.normal.size() != texels ||
      image.coverage.size() != texels) {
    error =
        filename + ": geometry image arrays do not match its size " + std::to_string(image.size);
    return false;
  }
  if (!image.albedo.empty() && image.albedo.size() != texels) {
    error =
        filename + ": geometry image albedo does not match its size " + std::to_string(image.size);
    return false;
  }
  if (!valid_ray_offset(image.ray_offset)) {
    error = filename + ": ray offset " + std::to_string(image.ray_offset) + " out of range";
    return false;
  }
  Imf::Header header = make_header(image.size, image.size, kImageTag, kGeometryImageVersion,
                                   image.box, image.source, image.build_id);
  header.insert("gfield.rayOffset", Imf::FloatAttribute(image.ray_offset));
  header.zipCompressionLevel() = 1;
  const Imf::PixelType type = pixel_type(precision);
  const float* p = &image.position[0].x;
  const float* n = &image.normal[0].x;
  const int w = image.size;
  OutputChannels out;
  out.add(header, "P.X", Imf::FLOAT, p + 0, 3, texels, w);
  out.add(header, "P.Y", Imf::FLOAT, p + 1, 3, texels, w);
  out.add(header, "P.Z", Imf::FLOAT, p + 2, 3, texels, w);
  out.add(header, "N.X", type, n + 0, 3, texels, w);
  out.add(header, "N.Y", type, n + 1, 3, texels, w);
  out.add(header, "N.Z", type, n + 2, 3, texels, w);
  out.add(header, "A", type, image.coverage.data(), 1, texels, w);
  if (!image.albedo.empty()) {
    const float* a = &image.albedo[0].x;
    for (int c = 0; c < 3; ++c) {
      out.add(header, kAlbedoChannels[c], type, a + c, 3, texels, w);
    }
  }
  return write_exr(filename, header, out.frame_buffer, image.size, error);
}

bool load_geometry_image(const std::string& filename, GeometryImage& image, std::string& error) {
  std::unique_ptr<Imf::InputFile> file;
  if (!open_input(filename, kMaxGeometryImageSide,
                  {"P.X", "P.Y", "P.Z", "N.X", "N.Y", "N.Z", "A", kAlbedoChannels[0],
                   kAlbedoChannels[1], kAlbedoChannels[2]},
                  file, error)) {
    return false;
  }
  ExrAssetHeader header;
  bool albedo = false;
  GeometryImage out;
  if (!read_header(filename, file->header(), header, error) ||
      !check_format(filename, header, kImageTag, 1, kGeometryImageVersion, error) ||
      !check_channels(filename, file->header(), {"P.X", "P.Y", "P.Z", "N.X", "N.Y", "N.Z", "A"},
                      error) ||
      !albedo_channels(filename, file->header(), albedo, error) ||
      !read_ray_offset(filename, file->header(), out.ray_offset, error)) {
    return false;
  }
  if (albedo && header.version < 2) {
    error = filename + ": albedo channels in a version-1 geometry image";
    return false;
  }
  if (header.width != header.height || header.width < 2) {
    error = filename + ": geometry image must be square and at least 2x2, found " +
            std::to_string(header.width) + "x" + std::to_string(header.height);
    return false;
  }
  out.size = header.width;
  out.box = header.box;
  out.source = header.source;
  out.build_id = header.build_id;
  const size_t texels = size_t(out.size) * size_t(out.size);
  out.position.resize(texels);
  out.normal.resize(texels);
  out.coverage.resize(texels);
  const Imath::Box2i dw = file->header().dataWindow();
  // OpenEXR addresses the frame buffer with absolute data-window coordinates.
  const ptrdiff_t origin = ptrdiff_t(dw.min.y) * out.size + dw.min.x;
  Imf::FrameBuffer fb;
  float* p = &out.position[0].x - origin * 3;
  float* n = &out.normal[0].x - origin * 3;
  fb.insert("P.X", float_slice(p + 0, 3, out.size));
  fb.insert("P.Y", float_slice(p + 1, 3, out.size));
  fb.insert("P.Z", float_slice(p + 2, 3, out.size));
  fb.insert("N.X", float_slice(n + 0, 3, out.size));
  fb.insert("N.Y", float_slice(n + 1, 3, out.size));
  fb.insert("N.Z", float_slice(n + 2, 3, out.size));
  fb.insert("A", float_slice(out.coverage.data() - origin, 1, out.size));
  if (albedo) {
    out.albedo.resize(texels);
    float* a = &out.albedo[0].x - origin * 3;
    for (int c = 0; c < 3; ++c) {
      fb.insert(kAlbedoChannels[c], float_slice(a + c, 3, out.size));
    }
  }
  if (!read_pixels(filename, *file, fb, error)) {
    return false;
  }
  if (!check_texels(filename, out, error)) {
    return false;
  }
  image = std::move(out);
  return true;
}

}  // namespace gfield
