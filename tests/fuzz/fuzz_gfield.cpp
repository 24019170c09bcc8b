// Fuzz target: geometry fields (load_geometry_field on NAME.gfield.exr).

#include "fuzz_support.hpp"
#include "gfield/exr_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  using namespace gfield;
  const std::string path = fuzz::write_input(data, size, "input.gfield.exr");
  GeometryField field;
  std::string error;
  if (!load_geometry_field(path, field, error)) {
    fuzz::check_error(path, error);
    return 0;
  }
  const size_t side = size_t(field_side(field));
  fuzz::check(field.samples_per_side >= 1 && field.samples_per_side <= 64, "N out of range");
  fuzz::check(field.layers >= 1 && field.layers <= kMaxFieldLayers, "layers out of range");
  fuzz::check(field.uv.size() == side * side * size_t(field.layers),
              "the table does not match N and the layers");
  for (const glm::vec2 uv : field.uv) {
    fuzz::check(is_field_hit(uv) ? uv.x <= 1.0f && uv.y <= 1.0f
                                 : uv.x == uv.y && (uv.x == kFieldMiss || uv.x == kFieldNoRay),
                "an invalid uv");
  }
  return 0;
}
