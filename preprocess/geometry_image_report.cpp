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
                                         {"flat_flips", r.proxy.flat_flips},
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
        {"area", rep.area},
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

namespace {

ErrorStats error_stats_from_json(const nlohmann::json& j) {
  return {j.at("mean_percent").get<double>(), j.at("p98_percent").get<double>(),
          j.at("p99_percent").get<double>(), j.at("max_percent").get<double>(),
          j.at("samples").get<size_t>()};
}

ChartReport chart_from_json(const nlohmann::json& j) {
  ChartReport c;
  c.faces = j.at("faces").get<size_t>();
  c.vertices = j.at("vertices").get<size_t>();
  c.genus = j.at("genus").get<long>();
  c.boundary_loops = j.at("boundary_loops").get<size_t>();
  c.route = j.at("route").get<std::string>();
  c.weights = j.at("weights").get<std::string>();
  c.note = j.at("note").get<std::string>();
  c.seam_edges = j.at("seam_edges").get<size_t>();
  c.flipped = j.at("flipped_faces").get<size_t>();
  c.degenerate = j.at("degenerate_faces").get<size_t>();
  c.area = j.at("area").get<double>();
  const nlohmann::json& rect = j.at("rect");
  c.rect = {rect.at(0).get<int>(), rect.at(1).get<int>(), rect.at(2).get<int>()};
  return c;
}

ProxyReport proxy_from_json(const nlohmann::json& j) {
  ProxyReport p;
  if (j.is_null())
    return p;
  p.used = j.at("used").get<bool>();
  p.input_faces = j.at("input_faces").get<size_t>();
  p.faces = j.at("faces").get<size_t>();
  p.error_percent = j.at("error_percent").get<double>();
  p.flat_flips = j.value("flat_flips", size_t(0));  // absent in reports of older builds
  p.mean_percent = j.at("mesh_to_image_mean_percent").get<double>();
  p.genus = j.at("genus").get<long>();
  p.input_genus = j.at("mesh_genus").get<long>();
  p.rejected = j.at("rejected").get<std::string>();
  return p;
}

RepairReport repair_from_json(const nlohmann::json& j) {
  RepairReport r;
  r.welded_positions = j.at("welded_positions").get<size_t>();
  r.unreferenced_positions = j.at("unreferenced_positions").get<size_t>();
  r.degenerate_faces = j.at("degenerate_faces").get<size_t>();
  r.duplicate_faces = j.at("duplicate_faces").get<size_t>();
  r.split_vertices = j.at("split_vertices").get<size_t>();
  r.reversed_components = j.at("reversed_components").get<size_t>();
  r.holes_found = j.at("holes_found").get<size_t>();
  r.holes_filled = j.at("holes_filled").get<size_t>();
  r.holes_fair_failed = j.at("holes_fair_failed").get<size_t>();
  r.filled_faces = j.at("filled_faces").get<size_t>();
  r.filled_area = j.at("filled_area").get<double>();
  r.area = j.at("area").get<double>();
  return r;
}

StageTimes stage_times_from_json(const nlohmann::json& j) {
  StageTimes t;
  t.proxy = j.at("proxy").get<double>();
  t.repair = j.at("repair").get<double>();
  t.parameterize = j.at("parameterize").get<double>();
  t.pack = j.at("pack").get<double>();
  t.rasterize = j.at("rasterize").get<double>();
  t.measure = j.at("measure").get<double>();
  t.total = j.at("total").get<double>();
  return t;
}

}  // namespace

GeometryImageReport geometry_image_report_from_json(const nlohmann::json& j) {
  GeometryImageReport r;
  if (const nlohmann::json& automatic = j.at("automatic_size"); !automatic.is_null()) {
    r.max_mean_error = automatic.at("max_mean_error_percent").get<double>();
    for (const nlohmann::json& t : automatic.at("trials"))
      r.size_trials.push_back(
          {t.at("size").get<int>(), t.at("mesh_to_image_mean_percent").get<double>()});
  }
  r.route = j.at("route").get<std::string>();
  r.proxy = proxy_from_json(j.at("proxy"));
  r.components = j.at("components").get<size_t>();
  r.dropped_components = j.at("dropped_components").get<size_t>();
  r.dropped_faces = j.at("dropped_faces").get<size_t>();
  for (const nlohmann::json& c : j.at("charts"))
    r.charts.push_back(chart_from_json(c));
  r.repair = repair_from_json(j.at("repair"));
  r.flipped = j.at("flipped_faces").get<size_t>();
  r.degenerate = j.at("degenerate_uv_faces").get<size_t>();
  r.coverage = j.at("coverage").get<double>();
  r.albedo = j.at("albedo").get<std::string>();
  r.conformal_mean = j.at("conformal_distortion").at("mean").get<double>();
  r.conformal_p95 = j.at("conformal_distortion").at("p95").get<double>();
  const nlohmann::json& area = j.at("area_distortion");
  r.area_p5 = area.at("p5").get<double>();
  r.area_p50 = area.at("p50").get<double>();
  r.area_p95 = area.at("p95").get<double>();
  const nlohmann::json& error = j.at("reconstruction_error");
  r.mesh_to_image = error_stats_from_json(error.at("mesh_to_image"));
  r.image_to_mesh = error_stats_from_json(error.at("image_to_mesh"));
  r.diagonal = error.at("diagonal").get<double>();
  r.ray_offset = j.at("ray_offset").get<double>();
  r.seconds = stage_times_from_json(j.at("seconds"));
  return r;
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
    add("proxy: %zu faces charted for %zu (meshoptimizer, error bound %.4f%% of the diagonal; %zu "
        "edges flipped where flat); texels projected onto the full surface",
        r.proxy.faces, r.proxy.input_faces, r.proxy.error_percent, r.proxy.flat_flips);
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
