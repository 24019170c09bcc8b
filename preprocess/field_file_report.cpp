// A field file's report as JSON, back from JSON, and as one line.

#include "preprocess/field_file_report.hpp"

#include <cstdio>

#include <nlohmann/json.hpp>

#include "gfield/box.hpp"
#include "gfield/gpu_storage.hpp"

namespace gfield {

nlohmann::json field_file_report_to_json(const FieldFileReport& r) {
  nlohmann::json coverage = nlohmann::json::object();
  for (int k = 1; k <= kMaxLineHits; ++k) {
    coverage[std::to_string(k)] = layer_coverage(r.build, k);
  }
  return {{"format_version", r.format},
          {"samples_per_side", r.samples_per_side},
          {"table_side", sample_count(r.samples_per_side)},
          {"layers", r.layers},
          {"lines_by_hits", r.build.lines_by_hits},
          {"lines_holding_all_hits_by_layers", coverage},
          {"line_table",
           {{"lines", r.table_lines}, {"words", r.line_words}, {"interior_hits", r.interior_hits}}},
          {"gpu_bytes",
           {{"geometry_image", geometry_image_gpu_bytes(r.image_size)},
            {"geometry_field_8bit", r.gpu_bytes[0]},
            {"geometry_field_16bit", r.gpu_bytes[1]},
            {"geometry_field_float", r.gpu_bytes[2]}}},
          {"memory_estimate_bytes", r.memory_estimate},
          {"rays", r.build.rays},
          {"hits", r.build.hits},
          {"bvh_seconds", r.bvh_seconds},
          {"cast_seconds", r.build.seconds},
          {"write_seconds", r.write_seconds},
          {"file_bytes", r.file_bytes}};
}

FieldFileReport field_file_report_from_json(const nlohmann::json& j) {
  FieldFileReport r;
  r.format = j.at("format_version").get<int>();
  r.samples_per_side = j.at("samples_per_side").get<int>();
  r.layers = j.at("layers").get<int>();
  r.build.lines_by_hits = j.at("lines_by_hits").get<decltype(r.build.lines_by_hits)>();
  const nlohmann::json& table = j.at("line_table");
  r.table_lines = table.at("lines").get<size_t>();
  r.line_words = table.at("words").get<size_t>();
  r.interior_hits = table.at("interior_hits").get<size_t>();
  const nlohmann::json& gpu = j.at("gpu_bytes");
  r.gpu_bytes = {gpu.at("geometry_field_8bit").get<size_t>(),
                 gpu.at("geometry_field_16bit").get<size_t>(),
                 gpu.at("geometry_field_float").get<size_t>()};
  r.memory_estimate = j.at("memory_estimate_bytes").get<size_t>();
  r.build.rays = j.at("rays").get<size_t>();
  r.build.hits = j.at("hits").get<size_t>();
  r.bvh_seconds = j.at("bvh_seconds").get<double>();
  r.build.seconds = j.at("cast_seconds").get<double>();
  r.write_seconds = j.at("write_seconds").get<double>();
  r.file_bytes = j.at("file_bytes").get<size_t>();
  return r;
}

std::string field_layers_summary(const FieldFileReport& r) {
  char line[240];
  if (r.format == kFieldFormatVersion) {
    std::snprintf(line, sizeof(line),
                  "format 3: up to %d hits per line (%.3f%% of the lines hold all theirs)",
                  r.layers, 100.0 * layer_coverage(r.build, kMaxLineHits));
  } else {
    std::snprintf(line, sizeof(line), "format 2: K = %d (%.3f%% of the lines hold all their hits)",
                  r.layers, 100.0 * layer_coverage(r.build, r.layers));
  }
  std::string text = line;
  std::snprintf(line, sizeof(line), ", GPU %.1f MB at 8 bits, %.1f MB at 16 bits (image %.1f MB)",
                double(r.gpu_bytes[0]) / 1e6, double(r.gpu_bytes[1]) / 1e6,
                double(geometry_image_gpu_bytes(r.image_size)) / 1e6);
  return text + line;
}

}  // namespace gfield
