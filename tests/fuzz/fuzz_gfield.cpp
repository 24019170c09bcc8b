// Fuzz target: geometry fields (load_geometry_field on NAME.gfield.exr).

#include "fuzz_support.hpp"
#include "gfield/exr_io.hpp"
#include "gfield/field_lines.hpp"

#include <algorithm>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  using namespace gfield;
  const std::string path = fuzz::write_input(data, size, "input.gfield.exr");
  GeometryField field;
  std::string error;
  if (!load_geometry_field(path, field, error)) {
    fuzz::check_error(path, error);
    return 0;
  }
  fuzz::check(field.samples_per_side >= 1 && field.samples_per_side <= 64, "N out of range");
  fuzz::check(field.layers >= 1 && field.layers <= kMaxLineHits, "layers out of range");
  fuzz::check(field.nearest.size() == field_nearest_size(field),
              "the nearest-hit table does not match N");
  for (const glm::vec2 uv : field.nearest) {
    fuzz::check(
        is_field_hit(uv) ? uv.x <= 1.0f && uv.y <= 1.0f : uv.x == kFieldMiss && uv.y == kFieldMiss,
        "an invalid nearest hit");
  }
  // Every line reads within the tables (the sanitizers see a read past them).
  const int side = field_side(field);
  int most = 0;
  for (int entry = 0; entry < side; ++entry) {
    for (int exit = 0; exit < side; ++exit) {
      if (entry / (side / 6) != exit / (side / 6)) {
        most = std::max(most, line_hits(field, entry, exit).count);
      }
    }
  }
  fuzz::check(most <= kMaxLineHits, "a line with more hits than a line holds");
  return 0;
}
