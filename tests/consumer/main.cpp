// consumer ASSET: loads ASSET.gfield.exr and ASSET.gimage.exr through an installed gfield::core
// and looks up two rays on the CPU: one aimed through the box's centre from outside (it must hit
// the surface inside the box, facing the ray) and one passing beside the box (it must miss).
// Exit 0 when both hold and the GLSL lookup library is installed; 1 otherwise.

#include <cstdio>
#include <filesystem>

#include <gfield/exr_io.hpp>
#include <gfield/field_lookup.hpp>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: consumer ASSET (ASSET.gfield.exr and ASSET.gimage.exr)\n");
    return 1;
  }
  const std::string asset = argv[1];
  gfield::GeometryField field;
  gfield::GeometryImage image;
  gfield::FieldLookup lookup;
  std::string error;
  if (!gfield::load_geometry_field(asset + ".gfield.exr", field, error) ||
      !gfield::load_geometry_image(asset + ".gimage.exr", image, error) ||
      !gfield::make_field_lookup(field, image, lookup, error)) {
    std::fprintf(stderr, "consumer: %s\n", error.c_str());
    return 1;
  }
  const glm::vec3 centre = 0.5f * (field.box.min + field.box.max);
  const glm::vec3 size = field.box.max - field.box.min;
  gfield::Ray through;
  through.origin = centre - glm::vec3(2.0f * size.x, 0.0f, 0.0f);
  through.direction = glm::vec3(1.0f, 0.0f, 0.0f);
  const gfield::FieldHit hit =
      gfield::lookup_first_hit(lookup, through, gfield::LookupMode::kRefined);
  gfield::Ray beside = through;
  beside.origin.y += 2.0f * size.y;
  const gfield::FieldHit miss =
      gfield::lookup_first_hit(lookup, beside, gfield::LookupMode::kRefined);
  std::printf("N = %d, hit %d at (%.4f %.4f %.4f) uv (%.4f %.4f), normal.x %.3f; beside: hit %d\n",
              field.samples_per_side, hit.hit, hit.position.x, hit.position.y, hit.position.z,
              hit.uv.x, hit.uv.y, hit.normal.x, miss.hit);
  const bool inside = glm::all(glm::greaterThanEqual(hit.position, field.box.min)) &&
                      glm::all(glm::lessThanEqual(hit.position, field.box.max));
  if (!hit.hit || !inside || hit.normal.x >= 0.0f || miss.hit) {
    std::fprintf(stderr, "consumer: unexpected lookup results\n");
    return 1;
  }
  if (!std::filesystem::is_regular_file(GFIELD_GLSL_LOOKUP)) {
    std::fprintf(stderr, "consumer: %s: not installed\n", GFIELD_GLSL_LOOKUP);
    return 1;
  }
  std::printf("GLSL lookup library: %s\n", GFIELD_GLSL_LOOKUP);
  return 0;
}
