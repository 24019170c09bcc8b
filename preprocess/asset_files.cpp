#include "preprocess/asset_files.hpp"

#include <filesystem>

#include "geometry/parameterized_mesh.hpp"
#include "gfield/build_id.hpp"
#include "gfield/exr_io.hpp"
#include "gfield/file_read.hpp"

namespace gfield {
namespace {

/// Reports are a few hundred kB; anything far larger is not one.
constexpr std::uint64_t kMaxReportBytes = 64ull << 20;

}  // namespace

AssetFiles asset_files(const std::string& name) {
  const std::string image = name + ".gimage.exr";
  return {image, parameterized_mesh_path(image), name + ".gfield.exr", name + ".report.json"};
}

std::string published_build(const std::string& name) {
  std::error_code ec;
  return std::filesystem::read_symlink(name + ".builds/current", ec).string();
}

bool read_report(const std::string& report_file, nlohmann::json& report, std::string& error) {
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

bool read_report_build_id(const std::string& report_file, std::string& build_id,
                          std::string& error) {
  nlohmann::json report;
  if (!read_report(report_file, report, error))
    return false;
  const auto id = report.find("build_id");
  build_id = id != report.end() && id->is_string() ? id->get<std::string>() : std::string();
  return true;
}

namespace {

bool carries(const std::string& file, const std::string& id, const std::string& wanted,
             std::string& why) {
  if (id != wanted) {
    why = file + ": " + describe_build_id(id) + ", not " + wanted;
  }
  return id == wanted;
}

}  // namespace

bool asset_is_build(const AssetFiles& files, const std::string& build_id, std::string& why) {
  std::string id;
  if (!read_report_build_id(files.report, id, why) || !carries(files.report, id, build_id, why)) {
    return false;
  }
  for (const std::string& exr : {files.image, files.field}) {
    ExrAssetHeader header;
    if (!load_asset_header(exr, header, why) || !carries(exr, header.build_id, build_id, why)) {
      return false;
    }
  }
  return read_parameterized_mesh_build_id(files.parameterized_mesh, id, why) &&
         carries(files.parameterized_mesh, id, build_id, why);
}

}  // namespace gfield
