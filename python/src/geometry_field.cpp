// gfield.GeometryField: a geometry field file, its table as a numpy array, and its CPU lookup
// vectorised over rays (the C++ lookup of gfield/field_lookup.hpp, ray by ray on every core).

#include <filesystem>

#include "gfield/asset_source.hpp"
#include "gfield/exr_io.hpp"
#include "gfield/field_lines.hpp"
#include "gfield/field_lookup.hpp"
#include "gfield/printable.hpp"
#include "gfield/published_build.hpp"
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
    if (!py::isinstance<py::str>(image) && !py::isinstance<py::bytes>(image) &&
        !py::hasattr(image, "__fspath__")) {
      throw py::type_error("image: expected None, a GeometryImage or a path, not " +
                           std::string(py::str(py::type::of(image).attr("__name__"))));
    }
    const auto path = image.cast<std::filesystem::path>();
    asset.image_file = path_text(path);
    asset.image = load_geometry_image_file(path);
  }
  std::string error;
  if (!make_field_lookup(asset.field, *asset.image, asset.lookup, error)) {
    throw Error(asset.file + ": does not match " + asset.image_file + " (" + error + ")");
  }
}

std::shared_ptr<FieldAsset> load_once(const std::string& file, const py::object& image) {
  auto asset = std::make_shared<FieldAsset>();
  asset->file = file;
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

/// Raises Error where the asset of `field_file` was not built from the mesh file `mesh` as it
/// is now (its report's record: size, then SHA-256; no report: nothing to check).
void check_built_from(const std::string& field_file, const py::object& mesh) {
  if (!py::isinstance<py::str>(mesh) && !py::isinstance<py::bytes>(mesh) &&
      !py::hasattr(mesh, "__fspath__")) {
    throw py::type_error("mesh: expected None or a path, not " +
                         std::string(py::str(py::type::of(mesh).attr("__name__"))));
  }
  const std::string name = asset_name_of(field_file);
  if (name.empty()) {
    throw Error(field_file + ": not named NAME.gfield.exr, so no report to check mesh= against");
  }
  std::string error;
  bool checked = false;
  if (!check_asset_source_of(name, path_text(mesh.cast<std::filesystem::path>()), checked, error)) {
    throw Error(error);
  }
}

std::shared_ptr<FieldAsset> load(const std::filesystem::path& path, const py::object& image,
                                 const py::object& mesh) {
  const std::string file = path_text(path);
  if (!mesh.is_none()) {
    check_built_from(file, mesh);
  }
  // An asset republished between the field's read and the image's gives files of two builds:
  // then both are read again, of the build published now (3 tries).
  const std::string name = asset_name_of(file);
  for (int attempt = 0;; ++attempt) {
    const std::string before = name.empty() ? "" : published_build(name);
    try {
      return load_once(file, image);
    } catch (const Error&) {
      if (attempt == 2 || before.empty() || published_build(name) == before) {
        throw;
      }
    }
  }
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
    const FieldHit h =
        lookup_first_hit(lookup, Ray{rays.origin(i), rays.direction(i), rays.start(i)}, mode);
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

/// The nearest-hit table as the GeometryField struct holds it: (6N^2, 5N^2, 2), viewed.
py::array nearest_view(const py::object& self) {
  const GeometryField& field = self.cast<const FieldAsset&>().field;
  return read_only_view(&field.nearest.data()->x,
                        {py::ssize_t(field_side(field)), py::ssize_t(field_columns(field)), 2},
                        self);
}

/// The layered table of `layers` hits per ray (format 2's): (K, 6N^2, 6N^2, 2), computed.
py::array layered_table(const FieldAsset& a, int layers) {
  const GeometryField& field = a.field;
  if (layers < 1 || layers > kMaxLineHits) {
    throw py::value_error("layers: expected 1 to " + std::to_string(kMaxLineHits) + ", got " +
                          std::to_string(layers));
  }
  const auto side = py::ssize_t(field_side(field));
  py::array_t<float> table({py::ssize_t(layers), side, side, py::ssize_t(2)});
  float* out = table.mutable_data();
  {
    py::gil_scoped_release release;
    const size_t count = size_t(side) * size_t(side);
    glm::vec2 uv[kMaxLineHits];
    for (size_t pair = 0; pair < count; ++pair) {
      layered_pair(field, int(pair / size_t(side)), int(pair % size_t(side)), layers, uv);
      for (int l = 0; l < layers; ++l) {
        out[2 * (size_t(l) * count + pair)] = uv[l].x;
        out[2 * (size_t(l) * count + pair) + 1] = uv[l].y;
      }
    }
  }
  return table;
}

/// Every hit of the line from `entry` towards `exit`: (k, 2).
py::array line_hits_array(const FieldAsset& a, int entry, int exit) {
  const GeometryField& field = a.field;
  const int side = field_side(field);
  if (entry < 0 || exit < 0 || entry >= side || exit >= side) {
    throw py::value_error("entry and exit: sample indices in [0, " + std::to_string(side) +
                          "), got " + std::to_string(entry) + ", " + std::to_string(exit));
  }
  if (field_uv(field, entry, exit).x == kFieldNoRay) {
    return py::array_t<float>(std::vector<py::ssize_t>{0, 2});
  }
  const LineHits hits = line_hits(field, entry, exit);
  py::array_t<float> out(std::vector<py::ssize_t>{hits.count, 2});
  for (int k = 0; k < hits.count; ++k) {
    out.mutable_at(k, 0) = hits.uv[size_t(k)].x;
    out.mutable_at(k, 1) = hits.uv[size_t(k)].y;
  }
  return out;
}

}  // namespace

void bind_geometry_field(py::module_& m) {
  py::class_<FieldAsset, std::shared_ptr<FieldAsset>>(
      m, "GeometryField",
      "A geometry field (NAME.gfield.exr, docs/geometry-field.md): for every line through two\n"
      "of the 6N^2 samples on the faces of the object's box, the geometry-image uvs of its\n"
      "hits; with its geometry image, lookups of any ray.")
      .def_static("load", &load, py::arg("path"), py::arg("image") = py::none(), py::kw_only(),
                  py::arg("mesh") = py::none(),
                  "Reads NAME.gfield.exr (format versions 1 to 3) and the geometry image it\n"
                  "indexes: `image` (a GeometryImage or a path) or, when None, NAME.gimage.exr\n"
                  "beside it if that exists (lookup needs one). mesh: None or the path of the\n"
                  "mesh file the asset must have been built from, as it is now (checked against\n"
                  "NAME.report.json: size, then SHA-256). An asset republished during the read\n"
                  "is read again, of the new build. Raises gfield.Error with the reader's\n"
                  "one-line message for a damaged file, when the image does not belong to the\n"
                  "field (box, source or build id), or when the asset was built from another\n"
                  "mesh than `mesh` (naming both files).")
      .def_property_readonly(
          "samples_per_side", [](const FieldAsset& a) { return a.field.samples_per_side; },
          "N, samples per side of each box face (6N^2 samples).")
      .def_property_readonly(
          "layers", [](const FieldAsset& a) { return a.field.layers; },
          "K, the hits a lookup reads per line: the most a line holds (format 3, at most 8),\n"
          "the layers of a format-2 file, 1 for format 1.")
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
      .def_property_readonly("nearest", &nearest_view,
                             "(6N^2, 5N^2, 2) float32, read-only: the nearest-hit table,\n"
                             "nearest[entry, column] the uv of the hit nearest sample `entry` on\n"
                             "the line towards the exit sample at `column` (the samples of the\n"
                             "five other faces in order, docs/formats.md); (-1, -1): a miss.")
      .def("line_hits", &line_hits_array, py::arg("entry"), py::arg("exit"),
           "(k, 2) float32: every hit of the line from sample `entry` towards sample `exit`\n"
           "(index face * N^2 + b * N + a, docs/formats.md), in order from `entry` (k = 0 for\n"
           "a line that misses or two samples on one face).")
      .def("table", &layered_table, py::arg("layers") = kMaxFieldLayers,
           "(K, 6N^2, 6N^2, 2) float32, computed: the layered table of format 2, table[l,\n"
           "entry, exit] the uv of hit l + 1 on the line from sample `entry` towards sample\n"
           "`exit`; (-1, -1): fewer hits, (-2, -2): both samples on one face. K = `layers`\n"
           "(1 to 8; 4 GB at N = 24 and K = 8).")
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
           "position and normal. Every ray is checked first: a non-finite origin, a zero,\n"
           "non-finite or huge direction (a coordinate beyond 1e18) or a NaN or negative t_min\n"
           "raises ValueError naming the argument and the row; a t_min that is not a number\n"
           "raises TypeError.")
      .def("__repr__", [](const FieldAsset& a) {
        return "<gfield.GeometryField N = " + std::to_string(a.field.samples_per_side) +
               ", K = " + std::to_string(a.field.layers) + " of " + printable(a.field.source) + ">";
      });
}

}  // namespace gfield::python
