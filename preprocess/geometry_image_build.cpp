// The geometry-image pipeline and its report.

#include "preprocess/geometry_image_build.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <unordered_map>

#include <glm/gtx/component_wise.hpp>

#include <nlohmann/json.hpp>

#include "geometry/edge_key.hpp"
#include "geometry/outward_normals.hpp"
#include "gfield/limits.hpp"
#include "gfield/stopwatch.hpp"
#include "preprocess/chart_split.hpp"
#include "preprocess/cut_graph.hpp"
#include "preprocess/parameterize.hpp"
#include "preprocess/rasterize.hpp"
#include "preprocess/surface_distance.hpp"
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

/// Area-weighted percentile (p in [0,1]) of values.
double weighted_percentile(std::vector<std::pair<double, double>> value_weight, double p) {
  if (value_weight.empty())
    return 0.0;
  std::sort(value_weight.begin(), value_weight.end());
  double total = 0.0;
  for (const auto& vw : value_weight)
    total += vw.second;
  double cumulative = 0.0;
  for (const auto& [value, weight] : value_weight) {
    cumulative += weight;
    if (cumulative >= p * total)
      return value;
  }
  return value_weight.back().first;
}

ErrorStats error_stats(std::vector<double> distances, double diagonal) {
  ErrorStats stats;
  stats.samples = distances.size();
  if (distances.empty() || !(diagonal > 0.0))
    return stats;
  std::sort(distances.begin(), distances.end());
  const double scale = 100.0 / diagonal;
  double sum = 0.0;
  for (double d : distances)
    sum += d;
  stats.mean = sum / double(distances.size()) * scale;
  const auto percentile = [&](double p) {
    const size_t k = size_t(std::ceil(p * double(distances.size()))) - 1;
    return distances[std::min(k, distances.size() - 1)] * scale;
  };
  stats.p98 = percentile(0.98);
  stats.p99 = percentile(0.99);
  stats.max = distances.back() * scale;
  return stats;
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

TriangleMesh geometry_image_surface(const GeometryImage& image) {
  TriangleMesh surface;
  const int n = image.size;
  surface.positions.resize(image.position.size());
  for (size_t t = 0; t < image.position.size(); ++t)
    surface.positions[t] = image.position[t];
  auto covered = [&](int i, int j) { return image.coverage[texel_index(image, i, j)] > 0.0f; };
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      if (!covered(i, j) || !covered(i + 1, j) || !covered(i, j + 1) || !covered(i + 1, j + 1))
        continue;
      const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      surface.triangles.push_back({a, b, d});
      surface.triangles.push_back({a, d, c});
    }
  return surface;
}

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

/// Conformal distortion (ratio of the map's singular values) of face f of the map surface ->
/// image uv, and its surface and uv areas; the ratio is -1 for a degenerate surface face.
double face_distortion(const ParameterizedMesh& parameterized, size_t f, double& surface_area,
                       double& uv_area) {
  const TriangleMesh& pm = parameterized.mesh;
  const glm::ivec3& t = pm.triangles[f];
  const glm::dvec3 e1 = pm.positions[t[1]] - pm.positions[t[0]];
  const glm::dvec3 e2 = pm.positions[t[2]] - pm.positions[t[0]];
  const glm::dvec2 u0 = parameterized.corner_uv[3 * f], u1 = parameterized.corner_uv[3 * f + 1],
                   u2 = parameterized.corner_uv[3 * f + 2];
  surface_area = 0.5 * glm::length(glm::cross(e1, e2));
  uv_area = 0.5 * std::abs((u1.x - u0.x) * (u2.y - u0.y) - (u1.y - u0.y) * (u2.x - u0.x));
  const double l1 = glm::length(e1);
  if (!(surface_area > 0.0) || !(l1 > 0.0))
    return -1.0;
  // Local frame of the surface triangle; J maps it onto the uv triangle.
  const glm::dvec2 q1(l1, 0.0), q2(glm::dot(e2, e1) / l1, 2.0 * surface_area / l1);
  const glm::dmat2 surface_edges(q1, q2), uv_edges(u1 - u0, u2 - u0);
  const glm::dmat2 j = uv_edges * glm::inverse(surface_edges);
  // Singular values of a 2x2 matrix.
  const double a = j[0][0], b = j[1][0], c = j[0][1], d = j[1][1];
  const double s1 = std::hypot(a + d, c - b) / 2.0, s2 = std::hypot(a - d, c + b) / 2.0;
  const double sigma1 = s1 + s2, sigma2 = std::abs(s1 - s2);
  return sigma2 > 0.0 ? sigma1 / sigma2 : 1e30;
}

/// Area-weighted conformal distortion and area-ratio percentiles of the map into `report`.
void measure_distortion(const ParameterizedMesh& parameterized, GeometryImageReport& report) {
  const size_t faces = parameterized.mesh.triangles.size();
  std::vector<double> surface_area(faces), uv_area(faces), sigma_ratio(faces);
  double surface_total = 0.0, uv_total = 0.0;
  for (size_t f = 0; f < faces; ++f) {
    sigma_ratio[f] = face_distortion(parameterized, f, surface_area[f], uv_area[f]);
    surface_total += surface_area[f];
    uv_total += uv_area[f];
  }
  // Degenerate uv faces (counted apart) are left out of the conformal distortion.
  std::vector<std::pair<double, double>> conformal, area_ratio;
  for (size_t f = 0; f < faces; ++f) {
    if (sigma_ratio[f] >= 1.0 && uv_area[f] > 1e-12 * uv_total)
      conformal.push_back({sigma_ratio[f], surface_area[f]});
    if (surface_area[f] > 0.0 && uv_total > 0.0)
      area_ratio.push_back(
          {(uv_area[f] / uv_total) / (surface_area[f] / surface_total), surface_area[f]});
  }
  double weighted = 0.0, weight = 0.0;
  for (const auto& [value, w] : conformal) {
    weighted += value * w;
    weight += w;
  }
  report.conformal_mean = weight > 0.0 ? weighted / weight : 0.0;
  report.conformal_p95 = weighted_percentile(conformal, 0.95);
  report.area_p5 = weighted_percentile(area_ratio, 0.05);
  report.area_p50 = weighted_percentile(area_ratio, 0.50);
  report.area_p95 = weighted_percentile(area_ratio, 0.95);
}

/// Bounding-box diagonal of `mesh` (mesh units).
double bounds_diagonal(const TriangleMesh& mesh) {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const glm::dvec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return glm::length(hi - lo);
}

/// With options.measure or an automatic size (which chooses by it): the mesh -> image distance
/// and the ray offset into `report` (report.diagonal set).
void measure_mesh_to_image(const TriangleMesh& input, const GeometryImage& image,
                           const GeometryImageOptions& options, GeometryImageReport& report) {
  if (!options.measure && options.size != kAutoImageSize)
    return;
  report.mesh_to_image =
      error_stats(distances_to_surface(sample_surface(input, options.error_samples, options.seed),
                                       geometry_image_surface(image)),
                  report.diagonal);
  const double box_diagonal = double(diagonal(image.box));
  if (box_diagonal > 0.0)
    report.ray_offset =
        std::clamp(report.mesh_to_image.p98 / 100.0 * report.diagonal / box_diagonal,
                   double(kMinRayOffset), double(kMaxRayOffset));
}

/// The distortion and the image -> mesh distance of the image kept into `report`.
void measure_image_to_mesh(const TriangleMesh& input, const GeometryImage& image,
                           const ParameterizedMesh& parameterized,
                           const GeometryImageOptions& options, GeometryImageReport& report) {
  measure_distortion(parameterized, report);
  report.image_to_mesh = error_stats(
      distances_to_surface(
          sample_surface(geometry_image_surface(image), options.error_samples, options.seed + 1),
          input),
      report.diagonal);
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
/// proxy's image holds (kProxyErrorFactor); report.proxy says what was tried. False only on
/// errors.
bool proxy_route(const TriangleMesh& input, const GeometryImageOptions& options,
                 const MeshAppearance* appearance, GeometryImage& image,
                 ParameterizedMesh& parameterized, GeometryImageReport& report,
                 std::string& error) {
  if (options.proxy_above == 0 || input.triangles.size() <= options.proxy_above)
    return true;
  Stopwatch stage;
  MeshProxy proxy;
  SurfaceProjection projection;
  if (!make_proxy(input, appearance, options, proxy, projection, report, error))
    return false;
  report.seconds.proxy = stage.seconds();
  if (!image_route(input, options, appearance, &proxy, &projection, image, parameterized, report,
                   error))
    return false;
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

nlohmann::json geometry_image_report_to_json(const GeometryImageReport& r) {
  using nlohmann::json;
  auto stats = [](const ErrorStats& s) {
    return json{{"mean_percent", s.mean},
                {"p98_percent", s.p98},
                {"p99_percent", s.p99},
                {"max_percent", s.max},
                {"samples", s.samples}};
  };
  json charts = json::array();
  for (const ChartReport& c : r.charts)
    charts.push_back({{"faces", c.faces},
                      {"vertices", c.vertices},
                      {"genus", c.genus},
                      {"boundary_loops", c.boundary_loops},
                      {"route", c.route},
                      {"weights", c.weights},
                      {"note", c.note},
                      {"seam_edges", c.seam_edges},
                      {"flipped_faces", c.flipped},
                      {"degenerate_faces", c.degenerate},
                      {"area", c.area},
                      {"rect", {c.rect.x, c.rect.y, c.rect.size}}});
  json trials = json::array();
  for (const SizeTrial& t : r.size_trials)
    trials.push_back({{"size", t.size}, {"mesh_to_image_mean_percent", t.mesh_to_image_mean}});
  const RepairReport& rep = r.repair;
  return json{
      {"automatic_size", r.size_trials.empty() ? json(nullptr)
                                               : json{{"max_mean_error_percent", r.max_mean_error},
                                                      {"trials", trials}}},
      {"route", r.route},
      {"proxy", r.proxy.faces > 0 ? json{{"used", r.proxy.used},
                                         {"input_faces", r.proxy.input_faces},
                                         {"faces", r.proxy.faces},
                                         {"error_percent", r.proxy.error_percent},
                                         {"mesh_to_image_mean_percent", r.proxy.mean_percent},
                                         {"genus", r.proxy.genus},
                                         {"mesh_genus", r.proxy.input_genus},
                                         {"rejected", r.proxy.rejected}}
                                  : json(nullptr)},
      {"components", r.components},
      {"dropped_components", r.dropped_components},
      {"dropped_faces", r.dropped_faces},
      {"charts", charts},
      {"repair",
       {{"welded_positions", rep.welded_positions},
        {"unreferenced_positions", rep.unreferenced_positions},
        {"degenerate_faces", rep.degenerate_faces},
        {"duplicate_faces", rep.duplicate_faces},
        {"split_vertices", rep.split_vertices},
        {"reversed_components", rep.reversed_components},
        {"holes_found", rep.holes_found},
        {"holes_filled", rep.holes_filled},
        {"holes_fair_failed", rep.holes_fair_failed},
        {"filled_faces", rep.filled_faces},
        {"filled_area", rep.filled_area},
        {"filled_area_percent", rep.area > 0.0 ? 100.0 * rep.filled_area / rep.area : 0.0}}},
      {"flipped_faces", r.flipped},
      {"degenerate_uv_faces", r.degenerate},
      {"coverage", r.coverage},
      {"albedo", r.albedo},
      {"conformal_distortion", {{"mean", r.conformal_mean}, {"p95", r.conformal_p95}}},
      {"area_distortion", {{"p5", r.area_p5}, {"p50", r.area_p50}, {"p95", r.area_p95}}},
      {"reconstruction_error",
       {{"mesh_to_image", stats(r.mesh_to_image)},
        {"image_to_mesh", stats(r.image_to_mesh)},
        {"diagonal", r.diagonal}}},
      {"ray_offset", r.ray_offset},
      {"seconds",
       {{"proxy", r.seconds.proxy},
        {"repair", r.seconds.repair},
        {"parameterize", r.seconds.parameterize},
        {"pack", r.seconds.pack},
        {"rasterize", r.seconds.rasterize},
        {"measure", r.seconds.measure},
        {"total", r.seconds.total}}}};
}

std::string geometry_image_report_to_text(const GeometryImageReport& r) {
  std::string text;
  char line[512];
  auto add = [&](const char* format, auto... values) {
    std::snprintf(line, sizeof(line), format, values...);
    text += line;
    text += '\n';
  };
  if (!r.size_trials.empty()) {
    std::string trials;
    for (const SizeTrial& t : r.size_trials) {
      std::snprintf(line, sizeof(line), "%s%d^2: %.4f%%", trials.empty() ? "" : ", ", t.size,
                    t.mesh_to_image_mean);
      trials += line;
    }
    const SizeTrial& kept = r.size_trials.back();
    add("size: %d^2, automatic (mean mesh -> image distance %s; target %.4f%%%s)", kept.size,
        trials.c_str(), r.max_mean_error,
        kept.mesh_to_image_mean > r.max_mean_error ? ", not reached at the largest size" : "");
  }
  if (r.proxy.used)
    add("proxy: %zu faces charted for %zu (meshoptimizer, error bound %.4f%% of the diagonal); "
        "texels projected onto the full surface",
        r.proxy.faces, r.proxy.input_faces, r.proxy.error_percent);
  else if (r.proxy.faces > 0)
    add("proxy: %zu faces tried for %zu and rejected (%s); built from the full mesh", r.proxy.faces,
        r.proxy.input_faces, r.proxy.rejected.c_str());
  add("route: %s", r.route.c_str());
  for (size_t c = 0; c < r.charts.size(); ++c) {
    const ChartReport& chart = r.charts[c];
    add("chart %zu: %zu faces, genus %ld, %zu boundary loops, %s (%s weights), %zu seam edges, "
        "%zu flipped, %zu degenerate, %dx%d texels at (%d, %d)%s%s",
        c, chart.faces, chart.genus, chart.boundary_loops, chart.route.c_str(),
        chart.weights.c_str(), chart.seam_edges, chart.flipped, chart.degenerate, chart.rect.size,
        chart.rect.size, chart.rect.x, chart.rect.y, chart.note.empty() ? "" : "; ",
        chart.note.c_str());
  }
  if (r.dropped_components)
    add("dropped: %zu smaller components (%zu faces) (--components largest)", r.dropped_components,
        r.dropped_faces);
  const RepairReport& rep = r.repair;
  add("repair: %zu positions welded, %zu degenerate and %zu duplicate faces dropped, %zu vertices "
      "split, %zu components turned outward",
      rep.welded_positions, rep.degenerate_faces, rep.duplicate_faces, rep.split_vertices,
      rep.reversed_components);
  add("holes: %zu found, %zu filled (%zu faces, area %.6g = %.3f%% of the surface)%s",
      rep.holes_found, rep.holes_filled, rep.filled_faces, rep.filled_area,
      rep.area > 0.0 ? 100.0 * rep.filled_area / rep.area : 0.0,
      rep.holes_fair_failed ? ", some unfaired" : "");
  add("uv faces: %zu flipped, %zu degenerate", r.flipped, r.degenerate);
  add("coverage: %.2f%% of the texels", 100.0 * r.coverage);
  add("albedo: %s", r.albedo.c_str());
  add("conformal distortion (sigma1/sigma2): mean %.3f, p95 %.3f", r.conformal_mean,
      r.conformal_p95);
  add("area distortion (uv share / surface share): p5 %.3g, p50 %.3g, p95 %.3g", r.area_p5,
      r.area_p50, r.area_p95);
  add("reconstruction error, mesh -> image (%% of diagonal %.4g): mean %.4f, p99 %.4f, max %.4f",
      r.diagonal, r.mesh_to_image.mean, r.mesh_to_image.p99, r.mesh_to_image.max);
  add("reconstruction error, image -> mesh: mean %.4f, p99 %.4f, max %.4f", r.image_to_mesh.mean,
      r.image_to_mesh.p99, r.image_to_mesh.max);
  add("ray offset: %.3g of the box diagonal (mesh -> image p98, at least %.0e)", r.ray_offset,
      double(kMinRayOffset));
  add("seconds: proxy %.3f, repair %.3f, parameterize %.3f, pack %.3f, rasterize %.3f, measure "
      "%.3f, total %.3f",
      r.seconds.proxy, r.seconds.repair, r.seconds.parameterize, r.seconds.pack,
      r.seconds.rasterize, r.seconds.measure, r.seconds.total);
  return text;
}

}  // namespace gfield
