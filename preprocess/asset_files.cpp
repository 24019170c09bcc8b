#include "preprocess/asset_files.hpp"

#include <filesystem>

#include "geometry/parameterized_mesh.hpp"
#include "gfield/build_id.hpp"
#include "gfield/exr_io.hpp"
#include "preprocess/asset_report.hpp"

namespace gfield {

AssetFiles asset_files(const std::string& name) {
  const std::string image = name + ".gimage.exr";
  return {image, parameterized_mesh_path(image), name + ".gfield.exr", name + ".report.json"};
}

bool read_report_build_id(const std::string& report_file, std::string& build_id,
                          std::string& error) {
  AssetReport report;
  if (!read_asset_report(report_file, report, error))
    return false;
  build_id = report.build_id;
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
