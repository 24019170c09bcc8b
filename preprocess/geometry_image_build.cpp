// The geometry-image pipeline: repair (or a proxy), charts, parameterisation, packing,
// rasterisation at each size tried; its measurements: image_measure.cpp, its report
// writers: geometry_image_report.cpp.

#include "preprocess/geometry_image_build.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <unordered_map>

#include <glm/gtx/component_wise.hpp>

#include "geometry/edge_key.hpp"
#include "geometry/outward_normals.hpp"
#include "gfield/limits.hpp"
#include "gfield/stopwatch.hpp"
#include "preprocess/chart_split.hpp"
#include "preprocess/cut_graph.hpp"
#include "preprocess/image_measure.hpp"
#include "preprocess/job_control.hpp"
#include "preprocess/parameterize.hpp"
#include "preprocess/rasterize.hpp"
#include "preprocess/surface_projection.hpp"

namespace gfield {
namespace {

/// One connected component of the repaired mesh, re-indexed.
struct Component {
  std::vector<int> faces;     ///< faces of the repaired mesh
  std::vector<int> vertices;  ///< local vertex -> repaired-mesh vertex
  TriangleMesh mesh;          ///< local copy
  size_t edges = 0;
  size_t boundary_loops = 0;
  long genus = 0;
  double area = 0.0;
};

/// The component made of `faces` of `mesh`: local copy, edges, boundary loops, genus.
Component make_component(const TriangleMesh& mesh, std::vector<int> faces) {
  Component c;
  c.faces = std::move(faces);
  std::unordered_map<int, int> local;
  local.reserve(c.faces.size());
  for (int f : c.faces) {
    glm::ivec3 t;
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles[f][k];
      auto [it, inserted] = local.emplace(v, int(c.vertices.size()));
      if (inserted) {
        c.vertices.push_back(v);
        c.mesh.positions.push_back(mesh.positions[v]);
      }
      t[k] = it->second;
    }
    c.mesh.triangles.push_back(t);
    const std::vector<glm::dvec3>& q = c.mesh.positions;
    c.area += 0.5 * glm::length(glm::cross(q[t[1]] - q[t[0]], q[t[2]] - q[t[0]]));
  }
  // Edges, boundary loops (each boundary vertex of an oriented manifold has one outgoing
  // boundary halfedge), genus from the Euler characteristic.
  std::unordered_map<uint64_t, int> directed;
  directed.reserve(3 * c.mesh.triangles.size());
  for (const glm::ivec3& t : c.mesh.triangles)
    for (int k = 0; k < 3; ++k)
      directed[half_edge_key(t[k], t[(k + 1) % 3])] = t[(k + 1) % 3];
  std::unordered_map<int, int> boundary_next;
  size_t interior = 0;
  for (const auto& [key, target] : directed) {
    const int source = half_edge_source(key);
    if (directed.count(half_edge_key(target, source)))
      ++interior;
    else
      boundary_next[target] = source;  // boundary halfedges, reversed: any consistent walk
  }
  c.edges = interior / 2 + boundary_next.size();
  std::unordered_map<int, char> visited;
  for (const auto& [start, next] : boundary_next) {
    if (visited.count(start))
      continue;
    ++c.boundary_loops;
    for (int v = start; !visited.count(v);) {
      visited[v] = 1;
      auto it = boundary_next.find(v);
      if (it == boundary_next.end())
        break;
      v = it->second;
    }
  }
  const long chi = long(c.mesh.positions.size()) - long(c.edges) + long(c.mesh.triangles.size());
  c.genus = (2 - chi - long(c.boundary_loops)) / 2;
  return c;
}

/// Connected components (faces sharing vertices), largest (by faces) first.
std::vector<Component> split_components(const TriangleMesh& mesh) {
  const std::vector<int> component = face_components(mesh);
  std::vector<std::vector<int>> faces;
  for (size_t f = 0; f < component.size(); ++f) {
    if (size_t(component[f]) >= faces.size())
      faces.resize(size_t(component[f]) + 1);
    faces[size_t(component[f])].push_back(int(f));
  }
  std::stable_sort(faces.begin(), faces.end(),
                   [](const auto& a, const auto& b) { return a.size() > b.size(); });
  std::vector<Component> components;
  for (std::vector<int>& f : faces)
    components.push_back(make_component(mesh, std::move(f)));
  return components;
}

/// Parameterises one component into a chart; fills the route fields of `chart_report`.
/// A protrusion (a disk cut from a chart) is slit from its tip (the vertex farthest from its
/// border) to the border so that the disk map unrolls it instead of shrinking the tip.
bool chart_component(const Component& c, size_t index, const GeometryImageOptions& options,
                     bool protrusion, Chart& chart, ChartReport& report, std::string& error) {
  const bool sphere = c.boundary_loops == 0 && c.genus == 0;
  const std::string what = "component " + std::to_string(index) + " (" +
                           std::to_string(c.faces.size()) + " faces, genus " +
                           std::to_string(c.genus) + ", " + std::to_string(c.boundary_loops) +
                           " boundary loops)";
  if (c.genus < 0) {
    error = what + ": not an orientable surface";
    return false;
  }
  if (c.faces.size() == 1) {  // a right triangle in its square
    chart = {};
    chart.corner_uv = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
    chart.weights = "none";
    report.route = "triangle";
    return true;
  }
  if (options.method == ParameterizationMethod::kOrbifold && !sphere) {
    error = what + ": the orbifold method needs closed genus-0 components (use --method auto)";
    return false;
  }
  if (sphere && options.method != ParameterizationMethod::kSquare) {
    std::string orbifold_error;
    if (parameterize_orbifold(c.mesh, chart, orbifold_error)) {
      report.route = "orbifold";
      return true;
    }
    if (options.method == ParameterizationMethod::kOrbifold) {
      error = what + ": " + orbifold_error;
      return false;
    }
    report.note = orbifold_error + "; fell back to a slit and a disk chart";
  }
  std::vector<Edge> cut;
  if (sphere) {
    const std::vector<int> ends = farthest_points(c.mesh, 2);
    cut = path_edges(shortest_path(c.mesh, ends[0], ends[1]));
    report.route = "slit+disk";
  } else if (c.genus == 0 && c.boundary_loops == 1 && protrusion) {
    std::vector<int> border;
    for (const Edge& e : boundary_edges(c.mesh))
      border.push_back(e[0]);
    const std::vector<double> from_border = edge_distances(c.mesh, border);
    int tip = 0;
    for (size_t v = 0; v < from_border.size(); ++v)
      if (from_border[v] > from_border[tip])
        tip = int(v);
    const std::vector<double> from_tip = edge_distances(c.mesh, {tip});
    int foot = border.empty() ? tip : border[0];
    for (int v : border)
      if (from_tip[v] < from_tip[foot])
        foot = v;
    cut = path_edges(shortest_path(c.mesh, tip, foot));
    report.route = cut.empty() ? "disk" : "slit+disk";
  } else if (c.genus == 0 && c.boundary_loops == 1) {
    report.route = "disk";
  } else {
    cut = tree_cotree_cut(c.mesh);
    report.route = "cut-graph+disk";
  }
  if (!parameterize_disk(c.mesh, cut, chart, error)) {
    error = what + ": " + error;
    return false;
  }
  return true;
}

/// A chart being built: its faces and topology, its uvs and its report.
struct Piece {
  Component component;
  Chart chart;
  ChartReport report;
};

/// Charts component `c` (index `index` in the report). While the chart compresses regions
/// (protrusions) and `depth` allows, those regions are cut out and charted on their own; the rest
/// keeps its uvs (an orbifold chart stays seamless). A split whose protrusions cannot all be
/// charted is abandoned for the unsplit chart.
bool chart_pieces(const TriangleMesh& mesh, Component c, size_t index, int depth, bool protrusion,
                  const GeometryImageOptions& options, std::vector<Piece>& out,
                  std::string& error) {
  Piece piece;
  if (!chart_component(c, index, options, protrusion, piece.chart, piece.report, error))
    return false;
  if (options.split_protrusions && depth < options.max_split_depth && c.faces.size() >= 64) {
    std::vector<std::vector<int>> groups =
        split_compressed_regions(c.mesh, piece.chart.corner_uv, SplitOptions{});
    if (!groups.empty()) {
      Piece rest;
      rest.chart = piece.chart;
      rest.chart.corner_uv.clear();
      for (int f : groups[0])
        for (int k = 0; k < 3; ++k)
          rest.chart.corner_uv.push_back(piece.chart.corner_uv[3 * f + k]);
      count_uv_faults(rest.chart.corner_uv, rest.chart.flipped, rest.chart.degenerate);
      rest.report = piece.report;
      rest.report.note = std::to_string(groups.size() - 1) + " protrusions cut out";
      std::vector<Piece> split;
      bool ok = true;
      for (size_t g = 1; g < groups.size() && ok; ++g) {
        std::vector<int> faces;
        for (int f : groups[g])
          faces.push_back(c.faces[f]);  // component-local -> mesh face
        std::string ignored;
        ok = chart_pieces(mesh, make_component(mesh, std::move(faces)), index, depth + 1, true,
                          options, split, ignored);
      }
      if (ok) {
        std::vector<int> faces;
        for (int f : groups[0])
          faces.push_back(c.faces[f]);
        rest.component = make_component(mesh, std::move(faces));
        out.push_back(std::move(rest));
        for (Piece& p : split) {
          if (p.report.note.empty())
            p.report.note = "protrusion";
          out.push_back(std::move(p));
        }
        return true;
      }
    }
  }
  piece.component = std::move(c);
  out.push_back(std::move(piece));
  return true;
}

}  // namespace

namespace {

/// False with an error for an image size or face count outside the documented limits.
/// "1e-15"-style text of a length.
std::string length_text(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.3g", value);
  return text;
}

/// The mesh's size and place are within what float casts and float positions resolve
/// (kMinAssetDiagonal, kMaxAssetDiagonal, kMaxAssetOffsetRatio); else `error` says why.
bool check_mesh_extent(const TriangleMesh& mesh, std::string& error) {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const glm::dvec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const double diagonal = glm::length(hi - lo);
  const double offset = std::max(glm::compMax(glm::abs(lo)), glm::compMax(glm::abs(hi)));
  if (!(diagonal >= kMinAssetDiagonal && diagonal <= kMaxAssetDiagonal)) {
    error = "the mesh is " + length_text(diagonal) + " units across (its bounding box's " +
            "diagonal): float casts lose a surface outside [" + length_text(kMinAssetDiagonal) +
            ", " + length_text(kMaxAssetDiagonal) + "] (scale the mesh)";
    return false;
  }
  if (offset > kMaxAssetOffsetRatio * diagonal) {
    error = "the mesh is " + length_text(diagonal) + " units across but " + length_text(offset) +
            " from the origin: float positions there are " + length_text(offset * 0x1p-23) +
            " apart (at most " + length_text(kMaxAssetOffsetRatio) +
            " times its size from the origin is accepted; move it towards the origin)";
    return false;
  }
  return true;
}

bool check_build_input(const TriangleMesh& input, const GeometryImageOptions& options,
                       std::string& error) {
  if (options.size != kAutoImageSize &&
      (options.size < kMinImageSize || options.size > kMaxImageSize)) {
    error = "image size " + std::to_string(options.size) + " is outside [" +
            std::to_string(kMinImageSize) + ", " + std::to_string(kMaxImageSize) + "]";
    return false;
  }
  if (options.size == kAutoImageSize &&
      !(options.max_mean_error > 0.0 && std::isfinite(options.max_mean_error))) {
    error = "the automatic image size's mean error " + std::to_string(options.max_mean_error) +
            " is not a positive percentage";
    return false;
  }
  if (input.triangles.size() > kMaxFaces) {
    error = "the mesh has " + std::to_string(input.triangles.size()) + " faces; at most " +
            std::to_string(kMaxFaces) + " are accepted (simplify it first)";
    return false;
  }
  if (input.triangles.empty()) {
    error = "the mesh has no faces";
    return false;
  }
  return check_mesh_extent(input, error);
}

/// Repairs `input` and splits it into components (the largest only, unless all are asked for).
bool repair_and_split(const TriangleMesh& input, const GeometryImageOptions& options,
                      RepairedMesh& repaired, std::vector<Component>& components,
                      GeometryImageReport& report, std::string& error) {
  if (!repair_mesh(input, options.holes, repaired, error))
    return false;
  report.repair = repaired.report;
  components = split_components(repaired.mesh);
  report.components = components.size();
  if (options.components == ComponentSelection::kLargest && components.size() > 1) {
    for (size_t c = 1; c < components.size(); ++c)
      report.dropped_faces += components[c].faces.size();
    report.dropped_components = components.size() - 1;
    components.resize(1);
  }
  return true;
}

/// Parameterises each component and the protrusions cut from it: one chart per piece, in
/// `components` and `charts` (same order), each reported.
bool parameterize_pieces(const TriangleMesh& mesh, std::vector<Component>& components,
                         const GeometryImageOptions& options, std::vector<Chart>& charts,
                         GeometryImageReport& report, std::string& error) {
  std::vector<Piece> pieces;
  for (size_t c = 0; c < components.size(); ++c)
    if (!chart_pieces(mesh, std::move(components[c]), c, 0, false, options, pieces, error))
      return false;
  components.clear();
  for (Piece& piece : pieces) {
    ChartReport& chart_report = piece.report;
    const Component& component = piece.component;
    chart_report.faces = component.faces.size();
    chart_report.vertices = component.vertices.size();
    chart_report.genus = component.genus;
    chart_report.boundary_loops = component.boundary_loops;
    chart_report.weights = piece.chart.weights;
    chart_report.seam_edges = piece.chart.seam_edges;
    chart_report.flipped = piece.chart.flipped;
    chart_report.degenerate = piece.chart.degenerate;
    chart_report.area = component.area;
    report.flipped += piece.chart.flipped;
    report.degenerate += piece.chart.degenerate;
    report.charts.push_back(chart_report);
    components.push_back(std::move(piece.component));
    charts.push_back(std::move(piece.chart));
  }
  return true;
}

/// The parameterised mesh: the charted faces with compact vertices (corner uvs come later) and
/// the input face of each.
ParameterizedMesh charted_mesh(const RepairedMesh& repaired,
                               const std::vector<Component>& components) {
  const TriangleMesh& mesh = repaired.mesh;
  ParameterizedMesh parameterized;
  std::vector<int> compact(mesh.positions.size(), -1);
  for (const Component& c : components)
    for (int f : c.faces) {
      parameterized.source_face.push_back(repaired.source_face[size_t(f)]);
      glm::ivec3 t;
      for (int k = 0; k < 3; ++k) {
        int& v = compact[mesh.triangles[f][k]];
        if (v < 0) {
          v = int(parameterized.mesh.positions.size());
          parameterized.mesh.positions.push_back(mesh.positions[mesh.triangles[f][k]]);
        }
        t[k] = v;
      }
      parameterized.mesh.triangles.push_back(t);
    }
  return parameterized;
}

/// Where a geometry image's texels come from: the charted mesh's own albedo, or (a proxy's image)
/// the full surface.
struct ImageSource {
  const AlbedoSource* albedo = nullptr;
  const SurfaceProjection* projection = nullptr;
};

/// Rasterises the packed charts into the size x size `image` (its box: the padded bounds of the
/// charted mesh) and gives the parameterised mesh its corner uvs.
void rasterize_image(const RepairedMesh& repaired, const std::vector<Component>& components,
                     const std::vector<Chart>& charts, const std::vector<ChartRect>& rects,
                     int size, const ImageSource& source, GeometryImage& image,
                     ParameterizedMesh& parameterized, GeometryImageReport& report) {
  const TriangleMesh& mesh = repaired.mesh;
  std::vector<RasterChart> raster(components.size());
  for (size_t c = 0; c < components.size(); ++c) {
    raster[c].faces = components[c].faces;
    raster[c].corner_uv = charts[c].corner_uv;
    raster[c].orbifold = charts[c].orbifold;
    raster[c].rect = rects[c];
    report.charts[c].rect = rects[c];
  }
  parameterized = charted_mesh(repaired, components);
  // A proxy's image holds the full surface, which its box must hold too.
  const std::vector<glm::dvec3>& bounded = source.projection != nullptr
                                               ? source.projection->surface().positions
                                               : parameterized.mesh.positions;
  std::vector<glm::vec3> box_points(bounded.begin(), bounded.end());
  image.box = padded_bounds(box_points.data(), box_points.size(), kBoxPadding);
  const std::vector<glm::dvec3> normals = angle_weighted_vertex_normals(mesh);
  std::vector<glm::vec2> face_uv;
  rasterize_charts(mesh, normals, raster, size, image.box, source.albedo, source.projection, image,
                   face_uv);
  for (const Component& c : components)
    for (int f : c.faces)
      for (int k = 0; k < 3; ++k)
        parameterized.corner_uv.push_back(face_uv[3 * size_t(f) + k]);
  size_t covered = 0;
  for (float a : image.coverage)
    covered += a > 0.0f;
  report.coverage = double(covered) / double(image.coverage.size());
}

/// "orbifold", or "orbifold + slit+disk x3": the charts' routes, counted.
std::string route_summary(const std::vector<ChartReport>& charts) {
  std::vector<std::pair<std::string, int>> routes;
  for (const ChartReport& chart : charts) {
    auto it = std::find_if(routes.begin(), routes.end(),
                           [&](const auto& r) { return r.first == chart.route; });
    if (it == routes.end())
      routes.push_back({chart.route, 1});
    else
      ++it->second;
  }
  std::string summary;
  for (size_t r = 0; r < routes.size(); ++r)
    summary += (r ? " + " : "") + routes[r].first +
               (routes[r].second > 1 ? " x" + std::to_string(routes[r].second) : "");
  return summary;
}

/// The charts packed and rasterised at `size` texels per side (`parameterized` rebuilt), their
/// mesh -> image distance measured (measure_mesh_to_image), the stage times added to `report`.
bool image_at_size(const TriangleMesh& input, const RepairedMesh& repaired,
                   const std::vector<Component>& components, const std::vector<Chart>& charts,
                   const ImageSource& source, const GeometryImageOptions& options, int size,
                   GeometryImage& image, ParameterizedMesh& parameterized,
                   GeometryImageReport& report, std::string& error) {
  Stopwatch stage;
  std::vector<double> areas;
  for (const Component& c : components)
    areas.push_back(c.area);
  std::vector<ChartRect> rects;
  if (!pack_charts(areas, size, options.gutter, rects, error))
    return false;
  report.seconds.pack += stage.seconds();
  stage.restart();
  image = {};
  rasterize_image(repaired, components, charts, rects, size, source, image, parameterized, report);
  report.seconds.rasterize += stage.seconds();
  stage.restart();
  measure_mesh_to_image(input, image, options, report);
  image.ray_offset = float(report.ray_offset);
  report.seconds.measure += stage.seconds();
  return true;
}

/// "1 texture, 2 materials, vertex colours": what `appearance`'s base colour is made of.
std::string albedo_summary(const MeshAppearance& appearance) {
  std::string text;
  const auto add = [&](size_t n, const char* what) {
    if (n > 0)
      text += (text.empty() ? "" : ", ") + std::to_string(n) + " " + what + (n > 1 ? "s" : "");
  };
  add(appearance.textures.size(), "texture");
  add(appearance.materials.size(), "material");
  if (!appearance.vertex_color.empty())
    text += std::string(text.empty() ? "" : ", ") + "vertex colours";
  return text;
}

/// The proxy of a mesh above options.proxy_above faces and the projection onto its full surface
/// (`appearance`: null or carrying a base colour), reported.
bool make_proxy(const TriangleMesh& input, const MeshAppearance* appearance,
                const GeometryImageOptions& options, MeshProxy& proxy,
                SurfaceProjection& projection, GeometryImageReport& report, std::string& error) {
  if (!make_mesh_proxy(input, options.proxy_above / 2, proxy, error))
    return false;
  const double diagonal = bounds_diagonal(input);
  // The proxy's surface lies within its error bound of the mesh; the reach leaves a margin.
  if (!projection.build(input, appearance, proxy.welded, 4.0 * proxy.error + 1e-4 * diagonal,
                        error))
    return false;
  report.proxy.input_faces = input.triangles.size();
  report.proxy.faces = proxy.proxy.triangles.size();
  report.proxy.error_percent = diagonal > 0.0 ? 100.0 * proxy.error / diagonal : 0.0;
  report.proxy.flat_flips = proxy.flat_flips;
  return true;
}

}  // namespace

namespace {

/// The image of `input` through `proxy` (and `projection` onto the input), or of `input` itself
/// (null): repair, charts, parameterisation, and the automatic size's trials, into `report`.
bool image_route(const TriangleMesh& input, const GeometryImageOptions& options,
                 const MeshAppearance* appearance, const MeshProxy* proxy,
                 const SurfaceProjection* projection, GeometryImage& image,
                 ParameterizedMesh& parameterized, GeometryImageReport& report,
                 std::string& error) {
  Stopwatch stage;
  RepairedMesh repaired;
  std::vector<Component> components;
  if (!repair_and_split(proxy != nullptr ? proxy->proxy : input, options, repaired, components,
                        report, error))
    return false;
  report.seconds.repair = stage.seconds();
  stage.restart();
  std::vector<Chart> charts;
  if (!parameterize_pieces(repaired.mesh, components, options, charts, report, error))
    return false;
  report.seconds.parameterize = stage.seconds();
  const MeshAppearance none;
  const AlbedoSource own_albedo(input, appearance != nullptr ? *appearance : none, repaired.mesh,
                                repaired.source_face);
  ImageSource source;
  if (projection != nullptr)
    source.projection = projection;
  else if (appearance != nullptr)
    source.albedo = &own_albedo;
  report.albedo = appearance != nullptr ? albedo_summary(*appearance) : "none";
  report.route = route_summary(report.charts);
  report.diagonal = bounds_diagonal(input);
  const bool automatic = options.size == kAutoImageSize;
  report.max_mean_error = automatic ? options.max_mean_error : 0.0;
  for (size_t trial = 0;; ++trial) {
    const int size = automatic ? kAutoImageSizes[trial] : options.size;
    if (!image_at_size(input, repaired, components, charts, source, options, size, image,
                       parameterized, report, error))
      return false;
    if (!automatic)
      break;
    report.size_trials.push_back({size, report.mesh_to_image.mean});
    if (report.mesh_to_image.mean <= options.max_mean_error ||
        trial + 1 == std::size(kAutoImageSizes))
      break;
  }
  return true;
}

/// The image through a proxy where `input` has more than options.proxy_above faces and the
/// proxy's image holds (kProxyErrorFactor); report.proxy says what was tried. A proxy that
/// cannot be made or charted (a stage's error: the simplified surface can fold where the mesh
/// does not) is rejected too, and the full route builds the mesh: a proxy never gives an error
/// that a full build would not. False only when interrupted.
bool proxy_route(const TriangleMesh& input, const GeometryImageOptions& options,
                 const MeshAppearance* appearance, GeometryImage& image,
                 ParameterizedMesh& parameterized, GeometryImageReport& report,
                 std::string& error) {
  if (options.proxy_above == 0 || input.triangles.size() <= options.proxy_above)
    return true;
  Stopwatch stage;
  MeshProxy proxy;
  SurfaceProjection projection;
  std::string failure;
  const bool made = make_proxy(input, appearance, options, proxy, projection, report, failure);
  report.seconds.proxy = stage.seconds();
  if (!made || !image_route(input, options, appearance, &proxy, &projection, image, parameterized,
                            report, failure)) {
    if (failure.find(kInterrupted) != std::string::npos) {
      error = failure;
      return false;
    }
    GeometryImageReport fresh;
    fresh.proxy = std::move(report.proxy);
    fresh.proxy.used = false;
    fresh.proxy.rejected = "its route failed: " + failure;
    fresh.seconds.proxy = stage.seconds();
    report = std::move(fresh);
    return true;
  }
  ProxyReport& p = report.proxy;
  p.mean_percent = report.mesh_to_image.mean;
  p.input_genus = proxy.genus;
  p.genus = 0;
  for (const ChartReport& chart : report.charts)
    p.genus += std::max(0L, chart.genus);  // pieces cut from a chart count their own
  char why[160] = "";
  if (p.input_genus >= 0 && p.genus > p.input_genus)
    std::snprintf(why, sizeof(why), "its charts have genus %ld, the mesh %ld", p.genus,
                  p.input_genus);
  else if (options.size == kAutoImageSize &&
           report.mesh_to_image.mean > kProxyErrorFactor * options.max_mean_error)
    std::snprintf(why, sizeof(why),
                  "its image's mean mesh -> image distance %.4f%% exceeds %g times the target",
                  report.mesh_to_image.mean, kProxyErrorFactor);
  p.rejected = why;
  p.used = p.rejected.empty();
  if (!report.proxy.used) {  // the full route starts over; what the proxy cost stays counted
    GeometryImageReport fresh;
    fresh.proxy = std::move(report.proxy);
    fresh.seconds.proxy = stage.seconds();
    report = std::move(fresh);
  }
  return true;
}

}  // namespace

bool build_geometry_image(const TriangleMesh& input, const GeometryImageOptions& options,
                          GeometryImage& image, ParameterizedMesh& parameterized,
                          GeometryImageReport& report, std::string& error,
                          const MeshAppearance* appearance) {
  Stopwatch watch;
  report = GeometryImageReport();
  if (!check_build_input(input, options, error))
    return false;
  const MeshAppearance* albedo =
      appearance != nullptr && carries_base_color(*appearance) ? appearance : nullptr;
  if (!proxy_route(input, options, albedo, image, parameterized, report, error))
    return false;
  if (!report.proxy.used &&
      !image_route(input, options, albedo, nullptr, nullptr, image, parameterized, report, error))
    return false;
  if (options.measure) {  // of the image kept only
    Stopwatch stage;
    measure_image_to_mesh(input, image, parameterized, options, report);
    report.seconds.measure += stage.seconds();
  }
  report.seconds.total = watch.seconds();
  return true;
}

}  // namespace gfield
