// The geometry-image report (GeometryImageReport) as JSON and as text.

#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "preprocess/geometry_image_build.hpp"

namespace gfield {

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
  else if (!r.proxy.rejected.empty())
    add("proxy: rejected (%s); built from the full mesh", r.proxy.rejected.c_str());
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
