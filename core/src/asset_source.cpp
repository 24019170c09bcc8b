#include "gfield/asset_source.hpp"

#include <algorithm>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "gfield/content_hash.hpp"
#include "gfield/file_read.hpp"

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
  return inputs != report.end() && built_mesh_from_inputs(*inputs, mesh);
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
  std::string text;
  if (!read_file(report_file, kMaxReportBytes, text, error))
    return false;
  BuiltMesh built;
  if (!built_mesh_from_report(nlohmann::json::parse(text, nullptr, false), built)) {
    error = report_file + ": no record of the mesh it was built from (inputs.mesh); rebuild it";
    return false;
  }
  if (const std::string problem = file_problem(mesh_file); !problem.empty()) {
    error = mesh_file + ": " + problem;
    return false;
  }
  std::error_code ec;
  const std::uint64_t bytes = std::filesystem::file_size(mesh_file, ec);
  std::string hash;
  if (ec || bytes == built.bytes) {
    if (!sha256_file(mesh_file, hash, error))
      return false;
  }
  checked = true;
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

bool check_scene_assets(const Scene& scene, int& stale, std::string& error) {
  stale = -1;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const MeshAsset& mesh = scene.meshes[m];
    if (!mesh.part.empty() || mesh.geometry_image.empty())
      continue;
    const std::string report = asset_report_path(mesh.geometry_image);
    bool checked = false;
    if (report.empty() || check_asset_source(report, mesh.file, checked, error))
      continue;
    if (checked)
      stale = int(m);
    return false;
  }
  return true;
}

}  // namespace gfield
