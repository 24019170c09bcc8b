// gfield.GeometryField: a geometry field file, its table as a numpy array, and its CPU lookup
// vectorised over rays (the C++ lookup of gfield/field_lookup.hpp, ray by ray on every core).

#include <filesystem>

#include "gfield/exr_io.hpp"
#include "gfield/field_lookup.hpp"
#include "gfield/printable.hpp"
#include "python/src/bindings.hpp"
#include "python/src/ray_batch.hpp"

namespace gfield::python {
namespace {

/// A field and the geometry image it indexes (none when not found beside it nor given).
struct FieldAsset {
  std::string file;
  GeometryField field;
  std::shared_ptr<GeometryImage> image;
  std::string image_file;  ///< the image's file; without an image, where it was looked for
  FieldLookup lookup;      ///< points into `field` and `*image`
};

/// NAME.gimage.exr beside NAME.gfield.exr ("" for a file not named so).
std::string image_beside(const std::string& field_file) {
  const std::string suffix = ".gfield.exr";
  if (field_file.size() <= suffix.size() ||
      field_file.compare(field_file.size() - suffix.size(), suffix.size(), suffix) != 0) {
    return "";
  }
  return field_file.substr(0, field_file.size() - suffix.size()) + ".gimage.exr";
}

/// The geometry image of `asset` as `image` names it (None: the file beside the field, when it
/// is there).
void attach_image(FieldAsset& asset, const py::object& image) {
  if (image.is_none()) {
    asset.image_file = image_beside(asset.file);
    std::error_code ec;
    if (asset.image_file.empty() || !std::filesystem::exists(asset.image_file, ec)) {
      return;
    }
    asset.image = load_geometry_image_file(asset.image_file);
  } else if (py::isinstance<GeometryImage>(image)) {
    asset.image = image.cast<std::shared_ptr<GeometryImage>>();
    asset.image_file = "the geometry image of " + printable(asset.image->source);
  } else {
    const auto path = image.cast<std::filesystem::path>();
    asset.image_file = path_text(path);
    asset.image = load_geometry_image_file(path);
  }
  std::string error;
  if (!make_field_lookup(asset.field, *asset.image, asset.lookup, error)) {
    throw Error(asset.file + ": does not match " + asset.image_file + " (" + error + ")");
  }
}

std::shared_ptr<FieldAsset> load(const std::filesystem::path& path, const py::object& image) {
  auto asset = std::make_shared<FieldAsset>();
  asset->file = path_text(path);
  std::string error;
  bool loaded = false;
  {
    py::gil_scoped_release release;
    loaded = load_geometry_field(asset->file, asset->field, error);
  }
  if (!loaded) {
    throw Error(error);
  }
  attach_image(*asset, image);
  return asset;
}

py::dict lookup_rays(const FieldAsset& asset, const py::object& origins,
                     const py::object& directions, const py::object& t_min,
                     const std::string& mode_name) {
  LookupMode mode = LookupMode::kRefined;
  if (!parse_lookup_mode(mode_name, mode)) {
    throw py::value_error("mode: expected nearest, linear or refined, got " + mode_name);
  }
  if (!asset.image) {
    throw Error(asset.file + ": no geometry image to look up with (" +
                (asset.image_file.empty() ? std::string("none beside it") : asset.image_file) +
                " not found; pass image=)");
  }
  const RayBatch rays = ray_batch(origins, directions, t_min);
  auto hit = answer_array<bool>(rays.count);
  auto t = answer_array<float>(rays.count);
  auto distance = answer_array<float>(rays.count);
  auto position = answer_array<float>(rays.count, 3);
  auto normal = answer_array<float>(rays.count, 3);
  auto uv = answer_array<float>(rays.count, 2);
  bool* hit_out = hit.mutable_data();
  float* t_out = t.mutable_data();
  float* distance_out = distance.mutable_data();
  float* position_out = position.mutable_data();
  float* normal_out = normal.mutable_data();
  float* uv_out = uv.mutable_data();
  const FieldLookup& lookup = asset.lookup;
  for_each_ray(rays.count, [&](size_t i) {
    const FieldHit h = lookup_first_hit(
        lookup, Ray{rays.origin(i), rays.direction(i), rays.start(i), 3.0e38f}, mode);
    hit_out[i] = h.hit;
    t_out[i] = h.t;
    distance_out[i] = h.distance;
    uv_out[2 * i] = h.uv.x;
    uv_out[2 * i + 1] = h.uv.y;
    for (int a = 0; a < 3; ++a) {
      position_out[3 * i + size_t(a)] = h.position[a];
      normal_out[3 * i + size_t(a)] = h.normal[a];
    }
  });
  py::dict answer;
  answer["hit"] = hit;
  answer["t"] = t;
  answer["distance"] = distance;
  answer["position"] = position;
  answer["normal"] = normal;
  answer["uv"] = uv;
  return answer;
}

/// The table as the GeometryField struct holds it: K layers of (6N^2)^2 uvs (layer, entry
/// sample, exit sample, u/v), viewed. The one place that knows the field's storage.
py::array table_view(const py::object& self) {
  const GeometryField& field = self.cast<const FieldAsset&>().field;
  const auto side = py::ssize_t(field_side(field));
  return read_only_view(&field.uv.data()->x, {py::ssize_t(field.layers), side, side, 2}, self);
}

}  // namespace

void bind_geometry_field(py::module_& m) {
  py::class_<FieldAsset, std::shared_ptr<FieldAsset>>(
      m, "GeometryField",
      "A geometry field (NAME.gfield.exr, docs/geometry-field.md): for every pair of the 6N^2\n"
      "samples on the faces of the object's box (entry, exit), the geometry-image uvs of the\n"
      "first K hits of the line between them; with its geometry image, lookups of any ray.")
      .def_static("load", &load, py::arg("path"), py::arg("image") = py::none(),
                  "Reads NAME.gfield.exr (format versions 1 and 2) and the geometry image it\n"
                  "indexes: `image` (a GeometryImage or a path) or, when None, NAME.gimage.exr\n"
                  "beside it if that exists (lookup needs one). Raises gfield.Error with the\n"
                  "reader's one-line message for a damaged file, or when the image does not\n"
                  "belong to the field (box, source or build id).")
      .def_property_readonly(
          "samples_per_side", [](const FieldAsset& a) { return a.field.samples_per_side; },
          "N, samples per side of each box face (the table is 6N^2 x 6N^2).")
      .def_property_readonly(
          "layers", [](const FieldAsset& a) { return a.field.layers; },
          "K, hits stored per line (1 to 4).")
      .def_property_readonly(
          "box", [](const FieldAsset& a) { return box_to_python(a.field.box); },
          "(2, 3) float32: the box's min and max corners, mesh coordinates.")
      .def_property_readonly(
          "source", [](const FieldAsset& a) { return printable(a.field.source); },
          "File name of the mesh it was built from.")
      .def_property_readonly(
          "build_id", [](const FieldAsset& a) { return printable(a.field.build_id); },
          "The build's id ('' for files without one).")
      .def_property_readonly(
          "image", [](const FieldAsset& a) { return a.image; },
          "The GeometryImage it is looked up with, or None.")
      .def_property_readonly("table", &table_view,
                             "(K, 6N^2, 6N^2, 2) float32, read-only: table[l, entry, exit] is the\n"
                             "uv of hit l + 1 on the line from sample `entry` towards sample\n"
                             "`exit` (sample index face * N^2 + b * N + a, docs/formats.md);\n"
                             "(-1, -1): fewer hits, (-2, -2): both samples on one face.")
      .def("lookup", &lookup_rays, py::arg("origins"), py::arg("directions"),
           py::arg("t_min") = 0.0f, py::arg("mode") = "refined",
           "The first hit beyond t_min of R rays origin + t * direction (mesh coordinates),\n"
           "looked up in the field: the C++ CPU lookup (gfield/field_lookup.hpp, the GLSL\n"
           "lookup compiled as C++), bit for bit, on every core without the GIL.\n\n"
           "origins, directions: (R, 3) array-likes (float32 is used); t_min: a number or (R,);\n"
           "mode: 'nearest', 'linear' or 'refined'. Returns a dict of arrays: hit (R,) bool;\n"
           "t (R,) float32 along the unnormalised direction; distance (R,) float32 (t times\n"
           "|direction|); position (R, 3) float32; normal (R, 3) float32, unit; uv (R, 2)\n"
           "float32, geometry-image uv. A miss has t = distance = 0, uv = (-1, -1) and zero\n"
           "position and normal; so do rays with a non-finite origin or direction, a zero\n"
           "direction or a NaN t_min.")
      .def("__repr__", [](const FieldAsset& a) {
        return "<gfield.GeometryField N = " + std::to_string(a.field.samples_per_side) +
               ", K = " + std::to_string(a.field.layers) + " of " + printable(a.field.source) + ">";
      });
}

}  // namespace gfield::python
