#pragma once
// Whole assets: mesh file -> NAME.gimage.exr + NAME.gimage.obj + NAME.gfield.exr +
// NAME.report.json (the `gfield field`, `gfield build` and `gfield batch` commands). The files of
// one asset: asset_files.hpp.

#include <string>

#include <nlohmann/json.hpp>

#include "gfield/exr_io.hpp"
#include "preprocess/asset_report.hpp"
#include "preprocess/build_inputs.hpp"
#include "preprocess/field_build.hpp"
#include "preprocess/field_file_report.hpp"
#include "preprocess/geometry_image_build.hpp"
#include "preprocess/job_control.hpp"

namespace gfield {

/// How a field file is written: the format (kFieldFormatVersion, or kLayeredFieldVersion with
/// `layers` K, kAutoLayers: chosen) and the precision of its uvs.
struct FieldFileFormat {
  int version = kFieldFormatVersion;
  int layers = kAutoLayers;
  ExrPrecision precision = ExrPrecision::kHalf;
};

/// Casts the field of `pm` (the parameterised mesh of `image`) with N samples per side in the
/// image's box and writes it to `output` (atomically) in `format`. The field's source and build
/// id are the image's. False with an error "FILE: problem" (N or K out of range or too large
/// for memory included; "FILE: interrupted" when `control` asked to stop; it hears the stages
/// "field" and "write").
bool write_field_file(const GeometryImage& image, const ParameterizedMesh& pm, int samples_per_side,
                      const FieldFileFormat& format, const std::string& output,
                      FieldFileReport& report, std::string& error,
                      const JobControl* control = nullptr);

/// Rays per family of a build's accuracy report: enough for its hit/miss agreements to within
/// about 0.1 percentage point (their 95% intervals are in the report), at a fraction of the build's
/// time (`gfield verify` casts 1,000,000 by default).
inline constexpr size_t kDefaultVerifyRays = 10000;

struct AssetOptions {
  /// glTF: which of its meshes (MeshSource::part; "" the whole file). Hashed into the build id.
  std::string part;
  GeometryImageOptions image;  ///< size 512 by default
  int samples_per_side = 24;
  FieldFileFormat field;                    ///< format 3 (compact) by default
  size_t verify_rays = kDefaultVerifyRays;  ///< rays per family of the report's accuracy (0: skip)
  /// Files the mesh names outside its folder (MeshSource::outside_paths). Not hashed: it decides
  /// what is read, not what is made of it.
  OutsidePaths outside_paths = OutsidePaths::kRefused;
  /// Progress and stop (job_control.hpp; stages "mesh", "image", "field", "write", "verify").
  /// Not hashed.
  const JobControl* control = nullptr;
};

/// Every geometry-image option, as hashed into build ids (`gfield image`, `gfield build`).
nlohmann::json image_options_to_json(const GeometryImageOptions& options);
/// Every option of an asset build that changes an output (its build id's "options").
nlohmann::json asset_options_to_json(const AssetOptions& options);

/// The inputs of building `mesh_path` with `options` and their build id (build_inputs.hpp).
bool asset_build_inputs(const std::string& mesh_path, const AssetOptions& options,
                        BuildInputs& inputs, std::string& error);

/// Builds asset `name` (DIR/NAME) from `mesh_path` whose inputs are `inputs`: topology, geometry
/// image (with the mesh's albedo), field, accuracy. All four files carry inputs.build_id and are
/// written into a staging folder, then published together (asset_staging.hpp); the report
/// records the build id, the hashed inputs, the glTF mesh ("mesh_part") and the mesh's warnings
/// ("warnings": a missing texture, ...). False with an error "FILE: problem", and the old asset
/// untouched (also when options.control stopped it: the error then ends in kInterrupted).
bool build_asset(const std::string& mesh_path, const std::string& name, const AssetOptions& options,
                 const BuildInputs& inputs, AssetReport& report, std::string& error);

/// `gfield build MESH -o NAME`: the inputs and their build id (asset_build_inputs), NAME's folder
/// (created), what killed builds left there (remove_stale_staging; how many folders into
/// `stale_removed`), then build_asset. The report's "build_id" is the asset's.
bool build_asset_at(const std::string& mesh_path, const std::string& name,
                    const AssetOptions& options, AssetReport& report, size_t& stale_removed,
                    std::string& error);

}  // namespace gfield
