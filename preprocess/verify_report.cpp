// verify's figures as JSON and as text: an agreement's confidence interval, the accuracy of a
// run, the reference the asset describes, the readable report.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "preprocess/verify.hpp"

namespace gfield {

glm::dvec2 agreement_interval(size_t agree, size_t rays) {
  if (rays == 0)
    return {0.0, 1.0};
  const double z = 1.959963984540054, n = double(rays), p = double(agree) / n;
  const double centre = (p + z * z / (2.0 * n)) / (1.0 + z * z / n);
  const double half = z * std::sqrt(p * (1.0 - p) / n + z * z / (4.0 * n * n)) / (1.0 + z * z / n);
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

nlohmann::json accuracy_to_json(const AccuracyStats& s) {
  const glm::dvec2 interval = agreement_interval(s.agree, s.rays);
  return {{"rays", s.rays},
          {"hit_agreement", s.hit_agreement()},
          {"hit_agreement_ci95", {interval.x, interval.y}},
          {"exact_hits", s.exact_hits},
          {"answer_hits", s.answer_hits},
          {"both_hit", s.both_hit},
          {"position_error_percent_of_diagonal",
           {{"median", s.position_median}, {"p95", s.position_p95}, {"p99", s.position_p99}}},
          {"normal_error_degrees", {{"median", s.normal_median}, {"p95", s.normal_p95}}},
          {"seconds", s.seconds}};
}

const nlohmann::json& described_reference(const nlohmann::json& report) {
  const nlohmann::json& references = report["references"];
  return report.value("proxy", false) && references.size() > 1 ? references[1] : references[0];
}

std::string verify_report_to_text(const nlohmann::json& report) {
  std::ostringstream out;
  out << "verify " << report["name"].get<std::string>() << ": N = " << report["samples_per_side"]
      << ", K = " << report["layers"] << ", uv bits " << report["field_bits"] << ", image "
      << report["image_size"] << "^2, " << report["rays_per_family"] << " rays per family, seed "
      << report["seed"] << "\n";
  if (report.contains("ray_offset")) {
    out << "surface rays leave the surface " << report["ray_offset"].get<float>()
        << " of the box diagonal off it (the geometry image's ray offset)\n";
  }
  out << "position error in % of the box diagonal, normal error in degrees\n";
  char line[256];
  for (const nlohmann::json& r : report["references"]) {
    out << "against the " << r["mesh"].get<std::string>() << " mesh ("
        << r["path"].get<std::string>() << "):\n";
    std::snprintf(line, sizeof(line), "  %-24s %9s %8s %8s %8s %8s %8s %9s\n", "test", "hit/miss",
                  "median", "p95", "p99", "n.med", "n.p95", "Mrays/s");
    out << line;
    const auto row = [&](const std::string& label, const nlohmann::json& s) {
      const nlohmann::json& p = s["position_error_percent_of_diagonal"];
      const nlohmann::json& nrm = s["normal_error_degrees"];
      const double seconds = s["seconds"].get<double>();
      const double rate = seconds > 0.0 ? s["rays"].get<double>() / seconds / 1e6 : 0.0;
      std::snprintf(line, sizeof(line), "  %-24s %8.3f%% %8.4f %8.4f %8.4f %8.3f %8.3f %9.2f\n",
                    label.c_str(), 100.0 * s["hit_agreement"].get<double>(),
                    p["median"].get<double>(), p["p95"].get<double>(), p["p99"].get<double>(),
                    nrm["median"].get<double>(), nrm["p95"].get<double>(), rate);
      out << line;
    };
    row("table", r["table"]);
    for (const std::string prefix : {"box_rays", "view_rays", "surface_rays", "mirror_rays"}) {
      for (const auto& [family, modes] : r.items()) {
        if (family.rfind(prefix, 0) != 0) {
          continue;
        }
        for (const auto& [mode, s] : modes.items()) {
          row(family + " " + mode, s);
        }
      }
    }
    if (r.contains("near_hits")) {
      out << "  rays leaving the surface whose exact hit lies within 2 ray offsets (told from "
             "their start surface by facing only):";
      for (const auto& [family, share] : r["near_hits"].items()) {
        std::snprintf(line, sizeof(line), " %s %.3f%%", family.c_str(),
                      100.0 * share.get<double>());
        out << line;
      }
      out << "\n";
    }
  }
  if (report.contains("original_note")) {
    out << report["original_note"].get<std::string>() << "\n";
  }
  return out.str();
}

}  // namespace gfield
