// gfield.load_mesh, gfield.Mesh (its arrays and exact ray casts through Embree), gfield.info.

#include <cmath>
#include <memory>
#include <mutex>

#include "geometry/mesh_appearance.hpp"
#include "geometry/mesh_formats.hpp"
#include "geometry/mesh_io.hpp"
#include "gfield/field_lookup.hpp"
#include "gfield/printable.hpp"
#include "preprocess/embree_mesh.hpp"
#include "preprocess/mesh_info.hpp"
#include "python/src/bindings.hpp"
#include "python/src/json_object.hpp"
#include "python/src/ray_batch.hpp"

namespace gfield::python {
namespace {

/// Embree's ray checks abort beyond |coordinate| 1.844e18 (FLT_LARGE): rays beyond this miss.
constexpr float kMaxCastCoordinate = 1e18f;

/// A mesh as read from its file, and the Embree scene of its exact casts (built on first use).
struct Mesh {
  std::string file;
  TriangleMesh mesh;
  MeshAppearance appearance;
  std::vector<std::string> warnings;
  std::mutex embree_mutex;
  std::unique_ptr<EmbreeMesh> embree;

  const EmbreeMesh& scene() {
    const std::lock_guard<std::mutex> lock(embree_mutex);
    if (!embree) {
      auto built = std::make_unique<EmbreeMesh>();
      std::string error;
      if (!built->build(mesh, error)) {
        throw Error(file + ": " + error);
      }
      embree = std::move(built);
    }
    return *embree;
  }
};

MeshSource mesh_source(const std::filesystem::path& path, const std::string& part,
                       bool allow_outside_paths) {
  MeshSource source{path_text(path), part,
                    allow_outside_paths ? OutsidePaths::kAllowed : OutsidePaths::kRefused};
  source.texture_pixels = false;  // the arrays hold no texture: its header is checked, no more
  return source;
}

std::shared_ptr<Mesh> load(const std::filesystem::path& path, const std::string& part,
                           bool allow_outside_paths) {
  auto mesh = std::make_shared<Mesh>();
  mesh->file = path_text(path);
  std::string error;
  bool loaded = false;
  {
    py::gil_scoped_release release;
    loaded = load_mesh(mesh_source(path, part, allow_outside_paths), mesh->mesh, &mesh->appearance,
                       mesh->warnings, error);
  }
  if (!loaded) {
    throw Error(error);
  }
  warn(mesh->warnings);
  return mesh;
}

/// True when Embree may cast the ray (check_ray, and every coordinate within its limits).
bool castable(glm::vec3 origin, glm::vec3 direction, float t_min) {
  std::string why;
  return check_ray(Ray{origin, direction, t_min}, why) &&
         glm::all(glm::lessThanEqual(glm::abs(origin), glm::vec3(kMaxCastCoordinate))) &&
         glm::all(glm::lessThanEqual(glm::abs(direction), glm::vec3(kMaxCastCoordinate)));
}

py::dict intersect_rays(Mesh& mesh, const py::object& origins, const py::object& directions,
                        const py::object& t_min) {
  const RayBatch rays = ray_batch(origins, directions, t_min);
  const EmbreeMesh* embree = nullptr;
  {
    py::gil_scoped_release release;
    embree = &mesh.scene();
  }
  auto hit = answer_array<bool>(rays.count);
  auto t = answer_array<float>(rays.count);
  auto position = answer_array<float>(rays.count, 3);
  auto normal = answer_array<float>(rays.count, 3);
  auto triangle = answer_array<int32_t>(rays.count);
  auto barycentric = answer_array<float>(rays.count, 2);
  bool* hit_out = hit.mutable_data();
  float* t_out = t.mutable_data();
  float* position_out = position.mutable_data();
  float* normal_out = normal.mutable_data();
  int32_t* triangle_out = triangle.mutable_data();
  float* barycentric_out = barycentric.mutable_data();
  for_each_ray(rays.count, [&](size_t i) {
    const glm::vec3 o = rays.origin(i);
    const glm::vec3 d = rays.direction(i);
    const float t0 = rays.start(i);
    const RayHit h = castable(o, d, t0) ? intersect(*embree, o, d, t0) : RayHit{};
    const glm::vec3 p = h.hit ? o + h.t * d : glm::vec3(0.0f);
    const glm::vec3 n = h.hit ? glm::normalize(h.geometric_normal) : glm::vec3(0.0f);
    hit_out[i] = h.hit;
    t_out[i] = h.t;
    triangle_out[i] = h.triangle;
    barycentric_out[2 * i] = h.u;
    barycentric_out[2 * i + 1] = h.v;
    for (int a = 0; a < 3; ++a) {
      position_out[3 * i + size_t(a)] = p[a];
      normal_out[3 * i + size_t(a)] = n[a];
    }
  });
  py::dict answer;
  answer["hit"] = hit;
  answer["t"] = t;
  answer["position"] = position;
  answer["normal"] = normal;
  answer["triangle"] = triangle;
  answer["barycentric"] = barycentric;
  return answer;
}

py::object info(const std::filesystem::path& path, const std::string& part,
                bool allow_outside_paths) {
  MeshInfo mesh_info;
  std::vector<std::string> warnings;
  std::string error;
  bool read = false;
  {
    py::gil_scoped_release release;
    read = read_mesh_info(mesh_source(path, part, allow_outside_paths), mesh_info, warnings, error);
  }
  if (!read) {
    throw Error(error);
  }
  warn(warnings);
  return json_to_python(mesh_info_to_json(mesh_info, path_text(path)));
}

void bind_mesh_class(py::module_& m) {
  static_assert(sizeof(glm::dvec3) == 3 * sizeof(double) && sizeof(glm::ivec3) == 3 * sizeof(int));
  static_assert(sizeof(glm::vec3) == 3 * sizeof(float) && sizeof(glm::vec2) == 2 * sizeof(float));
  py::class_<Mesh, std::shared_ptr<Mesh>>(
      m, "Mesh",
      "A triangle mesh as its file stores it (gfield.load_mesh): no welding, no repair; polygons\n"
      "fan-triangulated. Its arrays are read-only views.")
      .def_property_readonly(
          "vertices",
          [](const py::object& self) {
            const Mesh& mesh = self.cast<const Mesh&>();
            return read_only_view(&mesh.mesh.positions.data()->x,
                                  {py::ssize_t(mesh.mesh.positions.size()), 3}, self);
          },
          "(V, 3) float64: vertex positions, mesh coordinates.")
      .def_property_readonly(
          "faces",
          [](const py::object& self) {
            const Mesh& mesh = self.cast<const Mesh&>();
            return read_only_view(&mesh.mesh.triangles.data()->x,
                                  {py::ssize_t(mesh.mesh.triangles.size()), 3}, self);
          },
          "(F, 3) int32: vertex indices of each triangle, in the file's winding order.")
      .def_property_readonly(
          "uvs",
          [](const py::object& self) -> py::object {
            const Mesh& mesh = self.cast<const Mesh&>();
            const auto& uv = mesh.appearance.corner_uv;
            if (uv.empty()) {
              return py::none();
            }
            return read_only_view(&uv.data()->x, {py::ssize_t(uv.size() / 3), 3, 2}, self);
          },
          "(F, 3, 2) float32: texture coordinates of each triangle's corners (OBJ convention: v\n"
          "up), or None when the file has none.")
      .def_property_readonly(
          "colors",
          [](const py::object& self) -> py::object {
            const Mesh& mesh = self.cast<const Mesh&>();
            const auto& color = mesh.appearance.vertex_color;
            if (color.empty()) {
              return py::none();
            }
            return read_only_view(&color.data()->x, {py::ssize_t(color.size()), 3}, self);
          },
          "(V, 3) float32: linear RGB vertex colours, or None when the file has none.")
      .def_property_readonly(
          "warnings",
          [](const Mesh& mesh) {
            std::vector<std::string> lines;
            for (const std::string& w : mesh.warnings) {
              lines.push_back(printable(w));
            }
            return lines;
          },
          "What the reader went on past (also issued as GfieldWarning).")
      .def("intersect", &intersect_rays, py::arg("origins"), py::arg("directions"),
           py::arg("t_min") = 0.0f,
           "Exact first hits of R rays origin + t * direction, t >= t_min, cast with Embree (the\n"
           "ground truth of gfield verify and of the reference tracer), on every core without\n"
           "the GIL.\n\n"
           "origins, directions: (R, 3) array-likes (float32 is used); t_min: a number or (R,).\n"
           "Returns a dict of arrays: hit (R,) bool; t (R,) float32 along the unnormalised\n"
           "direction; position (R, 3) float32; normal (R, 3) float32, the unit geometric normal\n"
           "(the winding's); triangle (R,) int32 (-1: miss); barycentric (R, 2) float32 (Embree's\n"
           "u, v: position = (1-u-v) p0 + u p1 + v p2). A miss has zeros. Every ray is checked\n"
           "before Embree sees it, as GeometryField.lookup checks it (ValueError, TypeError);\n"
           "a finite origin beyond 1e18 misses.")
      .def("__repr__", [](const Mesh& mesh) {
        return "<gfield.Mesh " + std::to_string(mesh.mesh.positions.size()) + " vertices, " +
               std::to_string(mesh.mesh.triangles.size()) + " triangles>";
      });
}

}  // namespace

void bind_mesh(py::module_& m) {
  bind_mesh_class(m);
  // The formats of geometry/mesh_formats.hpp (static: the docstring outlives this call).
  static const std::string load_mesh_doc =
      "Reads a mesh file (" + mesh_extension_list() +
      ") as `gfield info` reads it.\n\n"
      "mesh: glTF only, the mesh NAME or #INDEX ('' : every primitive of the file's scene,\n"
      "placed by its nodes). allow_outside_paths: read files the mesh names outside its\n"
      "folder (material libraries, glTF buffers and images). Textures are checked through\n"
      "their headers, not decoded. Raises gfield.Error with the reader's one-line message\n"
      "(FILE[:LINE]: problem) for bad input.";
  m.def("load_mesh", &load, py::arg("path"), py::kw_only(), py::arg("mesh") = "",
        py::arg("allow_outside_paths") = false, load_mesh_doc.c_str());
  m.def("info", &info, py::arg("path"), py::kw_only(), py::arg("mesh") = "",
        py::arg("allow_outside_paths") = false,
        "The topology report of a mesh file: the dict `gfield info --json` prints (vertices,\n"
        "triangles, edges, components with their genus, boundary loops, non-manifold edges,\n"
        "bounding box, appearance, ...). Arguments as for load_mesh; raises gfield.Error.");
}

}  // namespace gfield::python
