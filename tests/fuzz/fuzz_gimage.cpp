// Fuzz target: geometry images (load_geometry_image on NAME.gimage.exr).

#include <cmath>

#include "fuzz_support.hpp"
#include "gfield/exr_io.hpp"
#include "gfield/limits.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  using namespace gfield;
  const std::string path = fuzz::write_input(data, size, "input.gimage.exr");
  GeometryImage image;
  std::string error;
  if (!load_geometry_image(path, image, error)) {
    fuzz::check_error(path, error);
    return 0;
  }
  const size_t texels = size_t(image.size) * size_t(image.size);
  fuzz::check(image.size >= 2 && image.size <= kMaxGeometryImageSide, "size out of range");
  fuzz::check(image.position.size() == texels && image.normal.size() == texels &&
                  image.coverage.size() == texels,
              "arrays do not match the size");
  for (size_t t = 0; t < texels; ++t) {
    for (int k = 0; k < 3; ++k) {
      fuzz::check(std::abs(image.position[t][k]) <= kMaxAssetCoordinate, "a position out of range");
    }
  }
  fuzz::check(glm::all(glm::lessThan(image.box.min, image.box.max)), "an empty box");
  return 0;
}
