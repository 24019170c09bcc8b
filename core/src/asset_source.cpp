#include "gfield/asset_source.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "gfield/content_hash.hpp"
#include "gfield/file_read.hpp"
#include "gfield/published_build.hpp"

namespace gfield {
namespace {

constexpr std::uint64_t kMaxReportBytes = 64ull << 20;
const std::string kReportSuffix = ".report.json";

/// A SHA-256 hex digest shortened to its first 12 digits, as messages show it.
std::string short_hash(const std::string& hex) {
  return hex.substr(0, 12);
}

}  // namespace

bool built_mesh_from_inputs(const nlohmann::json& inputs, BuiltMesh& mesh) {
  if (!inputs.is_object())
    return false;
  const auto record = inputs.find("mesh");
  if (record == inputs.end() || !record->is_object())
    return false;
  const auto bytes = record->find("bytes"), sha256 = record->find("sha256");
  if (bytes == record->end() || !bytes->is_number_unsigned() || sha256 == record->end() ||
      !sha256->is_string())
    return false;
  mesh.bytes = bytes->get<std::uint64_t>();
  mesh.sha256 = sha256->get<std::string>();
  mesh.file = record->value("file", std::string("?"));
  return true;
}

bool built_mesh_from_report(const nlohmann::json& report, BuiltMesh& mesh) {
  if (!report.is_object())
    return false;
  const auto inputs = report.find("inputs");
  if (inputs == report.end() || !built_mesh_from_inputs(*inputs, mesh))
    return false;
  const auto modified = report.find("mesh_modified_ns");
  mesh.modified_ns =
      modified != report.end() && modified->is_number_integer() ? modified->get<std::int64_t>() : 0;
  return true;
}

bool read_report_json(const std::string& report_file, nlohmann::json& report, std::string& error) {
  std::string text;
  if (!read_file(report_file, kMaxReportBytes, text, error))
    return false;
  report = nlohmann::json::parse(text, nullptr, false);
  if (!report.is_object()) {
    error = report_file + ": not a JSON object";
    return false;
  }
  return true;
}

bool file_modified_ns(const std::string& file, std::int64_t& ns) {
  std::error_code ec;
  const auto time = std::filesystem::last_write_time(file, ec);
  if (ec)
    return false;
  ns = std::chrono::duration_cast<std::chrono::nanoseconds>(time.time_since_epoch()).count();
  return true;
}

std::string asset_report_path(const std::string& geometry_image) {
  const std::string suffix = ".gimage.exr";
  if (geometry_image.size() <= suffix.size() ||
      geometry_image.compare(geometry_image.size() - suffix.size(), suffix.size(), suffix) != 0)
    return "";
  return geometry_image.substr(0, geometry_image.size() - suffix.size()) + kReportSuffix;
}

bool check_asset_source(const std::string& report_file, const std::string& mesh_file, bool& checked,
                        std::string& error) {
  checked = false;
  if (file_problem(report_file) == "no such file")
    return true;
  nlohmann::json report;
  if (!read_report_json(report_file, report, error))
    return false;
  BuiltMesh built;
  if (!built_mesh_from_report(report, built)) {
    error = report_file + ": no record of the mesh it was built from (inputs.mesh); rebuild it";
    return false;
  }
  if (const std::string problem = file_problem(mesh_file); !problem.empty()) {
    error = mesh_file + ": " + problem;
    return false;
  }
  std::error_code ec;
  const std::uint64_t bytes = std::filesystem::file_size(mesh_file, ec);
  std::int64_t modified = 0;
  checked = true;
  if (!ec && bytes == built.bytes && built.modified_ns != 0 &&
      file_modified_ns(mesh_file, modified) && modified == built.modified_ns)
    return true;
  std::string hash;
  if (ec || bytes == built.bytes) {
    if (!sha256_file(mesh_file, hash, error))
      return false;
  }
  if (!ec && bytes == built.bytes && hash == built.sha256)
    return true;
  const std::string now =
      hash.empty() ? std::to_string(bytes) + " bytes" : "sha256 " + short_hash(hash);
  const std::string then =
      hash.empty() ? std::to_string(built.bytes) + " bytes" : "sha256 " + short_hash(built.sha256);
  const size_t stem = report_file.size() - std::min(report_file.size(), kReportSuffix.size());
  const std::string name = report_file.substr(0, stem);
  error = report_file + ": built from " + built.file + " (" + then + "), not from " + mesh_file +
          " as it is now (" + now + "); rebuild it: gfield build " + mesh_file + " -o " + name;
  return false;
}

bool check_asset_source_of(const std::string& name, const std::string& mesh_file, bool& checked,
                           std::string& error) {
  for (int attempt = 0;; ++attempt) {
    const std::string build = published_build(name);
    if (check_asset_source(name + std::string(kReportSuffix), mesh_file, checked, error))
      return true;
    if (checked || attempt == 2 || build.empty() || published_build(name) == build)
      return false;
  }
}

bool check_scene_assets(const Scene& scene, int& stale, std::string& error) {
  stale = -1;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const MeshAsset& mesh = scene.meshes[m];
    if (!mesh.part.empty() || mesh.geometry_image.empty())
      continue;
    const std::string name = asset_name_of(mesh.geometry_image);
    bool checked = false;
    if (name.empty() || check_asset_source_of(name, mesh.file, checked, error))
      continue;
    if (checked)
      stale = int(m);
    return false;
  }
  return true;
}

}  // namespace gfield
