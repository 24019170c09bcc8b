#include "preprocess/build_inputs.hpp"

#include <filesystem>

#include "geometry/mesh_formats.hpp"
#include "gfield/asset_source.hpp"
#include "gfield/content_hash.hpp"
#include "gfield/file_read.hpp"
#include "gfield/printable.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

/// Scheme of the hashed record; bump when what it holds changes meaning.
/// 2: geometry images hold the mesh's albedo (format version 2).
constexpr int kBuildIdScheme = 2;

}  // namespace

bool hash_build_inputs(const std::string& mesh_path, const nlohmann::json& options,
                       OutsidePaths outside, BuildInputs& inputs, std::string& error) {
  if (const std::string problem = file_problem(mesh_path); !problem.empty()) {
    error = mesh_path + ": " + (problem == "no such file" ? "no such mesh file" : problem);
    return false;
  }
  std::error_code ec;
  std::string mesh_hash;
  if (!file_modified_ns(mesh_path, inputs.mesh_modified_ns))
    inputs.mesh_modified_ns = 0;
  if (!sha256_file(mesh_path, mesh_hash, error)) {
    return false;
  }
  nlohmann::json textures = nlohmann::json::array();
  const fs::path mesh_folder = fs::path(mesh_path).parent_path();
  for (const std::string& file : mesh_side_files(mesh_path, outside)) {
    std::string hash;
    std::string ignored;
    const bool found = fs::is_regular_file(file, ec) && sha256_file(file, hash, ignored);
    textures.push_back(
        {{"file", printable(fs::path(file).lexically_relative(mesh_folder).string())},
         {"sha256", found ? nlohmann::json(hash) : nlohmann::json()}});
  }
  inputs.record = {{"scheme", kBuildIdScheme},
                   {"gfield", GFIELD_VERSION},
                   {"mesh",
                    {{"file", printable(fs::path(mesh_path).filename().string())},
                     {"bytes", fs::file_size(mesh_path, ec)},
                     {"sha256", mesh_hash}}},
                   {"textures", std::move(textures)},
                   {"options", options}};
  inputs.build_id = sha256_hex(inputs.record.dump()).substr(0, kBuildIdDigits);
  return true;
}

}  // namespace gfield
