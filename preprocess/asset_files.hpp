#pragma once
// The four files of an asset DIR/NAME and whether they form one complete build: NAME.gimage.exr
// (geometry image), NAME.gimage.obj (parameterised mesh), NAME.gfield.exr (geometry field) and
// NAME.report.json (report), each carrying the build id (gfield/build_id.hpp).

#include <string>

#include "gfield/published_build.hpp"

namespace gfield {

struct AssetFiles {
  std::string image;
  std::string parameterized_mesh;
  std::string field;
  std::string report;
};

/// The files of asset `name` (a path without extension: DIR/NAME).
AssetFiles asset_files(const std::string& name);

/// The build id recorded in a report file. False with an error "FILE: problem" when the file
/// cannot be read or is not an asset report (read_asset_report).
bool read_report_build_id(const std::string& report_file, std::string& build_id,
                          std::string& error);

/// True when all four files exist and each carries `build_id`: the asset is that build,
/// complete. Otherwise false, with `why` saying what is missing or different.
bool asset_is_build(const AssetFiles& files, const std::string& build_id, std::string& why);

}  // namespace gfield
