// verify's figures as JSON and as text: an agreement's confidence interval, the accuracy of a
// run, the reference the asset describes, the readable report.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "preprocess/verify_report.hpp"

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

AccuracyStats accuracy_from_json(const nlohmann::json& j) {
  AccuracyStats s;
  s.rays = j.at("rays").get<size_t>();
  s.agree = size_t(std::llround(j.at("hit_agreement").get<double>() * double(s.rays)));
  s.exact_hits = j.at("exact_hits").get<size_t>();
  s.answer_hits = j.at("answer_hits").get<size_t>();
  s.both_hit = j.at("both_hit").get<size_t>();
  const nlohmann::json& position = j.at("position_error_percent_of_diagonal");
  s.position_median = position.at("median").get<double>();
  s.position_p95 = position.at("p95").get<double>();
  s.position_p99 = position.at("p99").get<double>();
  const nlohmann::json& normal = j.at("normal_error_degrees");
  s.normal_median = normal.at("median").get<double>();
  s.normal_p95 = normal.at("p95").get<double>();
  s.seconds = j.at("seconds").get<double>();
  return s;
}

const ReferenceAccuracy& VerifyReport::described() const {
  return proxy && references.size() > 1 ? references[1] : references.at(0);
}

namespace {

// The keys of a reference's JSON object that are not ray families.
const char* const kReferenceKeys[] = {"mesh", "path", "table", "near_hits"};

nlohmann::json reference_to_json(const ReferenceAccuracy& r) {
  nlohmann::json j = {{"mesh", r.mesh}, {"path", r.path}, {"table", accuracy_to_json(r.table)}};
  for (const auto& [family, modes] : r.families) {
    for (const auto& [mode, stats] : modes) {
      j[family][mode] = accuracy_to_json(stats);
    }
  }
  if (!r.near_hits.empty()) {
    j["near_hits"] = r.near_hits;
  }
  return j;
}

ReferenceAccuracy reference_from_json(const nlohmann::json& j) {
  ReferenceAccuracy r;
  r.mesh = j.at("mesh").get<std::string>();
  r.path = j.at("path").get<std::string>();
  r.table = accuracy_from_json(j.at("table"));
  if (j.contains("near_hits")) {
    r.near_hits = j["near_hits"].get<std::map<std::string, double>>();
  }
  for (const auto& [key, modes] : j.items()) {
    if (std::find(std::begin(kReferenceKeys), std::end(kReferenceKeys), key) !=
        std::end(kReferenceKeys)) {
      continue;
    }
    for (const auto& [mode, stats] : modes.items()) {
      r.families[key][mode] = accuracy_from_json(stats);
    }
  }
  return r;
}

}  // namespace

nlohmann::json verify_report_to_json(const VerifyReport& r) {
  nlohmann::json j = {{"name", r.name},
                      {"field", r.field},
                      {"samples_per_side", r.samples_per_side},
                      {"layers", r.layers},
                      {"field_bits", r.field_bits},
                      {"image_size", r.image_size},
                      {"ray_offset", r.ray_offset},
                      {"source", r.source},
                      {"rays_per_family", r.rays_per_family},
                      {"seed", r.seed},
                      {"proxy", r.proxy},
                      {"references", nlohmann::json::array()}};
  for (const ReferenceAccuracy& reference : r.references) {
    j["references"].push_back(reference_to_json(reference));
  }
  if (!r.original_note.empty()) {
    j["original_note"] = r.original_note;
  }
  return j;
}

VerifyReport verify_report_from_json(const nlohmann::json& j) {
  VerifyReport r;
  r.name = j.at("name").get<std::string>();
  r.field = j.at("field").get<std::string>();
  r.samples_per_side = j.at("samples_per_side").get<int>();
  r.layers = j.at("layers").get<int>();
  r.field_bits = j.at("field_bits").get<int>();
  r.image_size = j.at("image_size").get<int>();
  r.ray_offset = j.at("ray_offset").get<float>();
  r.source = j.at("source").get<std::string>();
  r.rays_per_family = j.at("rays_per_family").get<size_t>();
  r.seed = j.at("seed").get<uint64_t>();
  r.proxy = j.at("proxy").get<bool>();
  for (const nlohmann::json& reference : j.at("references")) {
    r.references.push_back(reference_from_json(reference));
  }
  if (r.references.empty()) {
    throw nlohmann::json::other_error::create(501, "no reference mesh", &j);
  }
  r.original_note = j.value("original_note", std::string());
  return r;
}

std::string verify_report_to_text(const VerifyReport& report) {
  std::ostringstream out;
  out << "verify " << report.name << ": N = " << report.samples_per_side
      << ", K = " << report.layers << ", uv bits " << report.field_bits << ", image "
      << report.image_size << "^2, " << report.rays_per_family << " rays per family, seed "
      << report.seed << "\n";
  out << "surface rays leave the surface " << report.ray_offset
      << " of the box diagonal off it (the geometry image's ray offset)\n";
  out << "position error in % of the box diagonal, normal error in degrees\n";
  char line[256];
  for (const ReferenceAccuracy& r : report.references) {
    out << "against the " << r.mesh << " mesh (" << r.path << "):\n";
    std::snprintf(line, sizeof(line), "  %-24s %9s %8s %8s %8s %8s %8s %9s\n", "test", "hit/miss",
                  "median", "p95", "p99", "n.med", "n.p95", "Mrays/s");
    out << line;
    const auto row = [&](const std::string& label, const AccuracyStats& s) {
      const double rate = s.seconds > 0.0 ? double(s.rays) / s.seconds / 1e6 : 0.0;
      std::snprintf(line, sizeof(line), "  %-24s %8.3f%% %8.4f %8.4f %8.4f %8.3f %8.3f %9.2f\n",
                    label.c_str(), 100.0 * s.hit_agreement(), s.position_median, s.position_p95,
                    s.position_p99, s.normal_median, s.normal_p95, rate);
      out << line;
    };
    row("table", r.table);
    for (const std::string prefix :
         {"box_rays", "view_rays", "surface_rays", "mirror_rays", "glass_rays"}) {
      for (const auto& [family, modes] : r.families) {
        if (family.rfind(prefix, 0) != 0) {
          continue;
        }
        for (const auto& [mode, s] : modes) {
          row(family + " " + mode, s);
        }
      }
    }
    if (!r.near_hits.empty()) {
      out << "  rays leaving the surface whose exact hit lies within 2 ray offsets (told from "
             "their start surface by facing only):";
      for (const auto& [family, share] : r.near_hits) {
        std::snprintf(line, sizeof(line), " %s %.3f%%", family.c_str(), 100.0 * share);
        out << line;
      }
      out << "\n";
    }
  }
  if (!report.original_note.empty()) {
    out << report.original_note << "\n";
  }
  return out.str();
}

}  // namespace gfield
