#pragma once
// The mesh file formats gfield reads, one row each: a new format is a row here, its reader and
// its seeds for the fuzzer (docs/architecture.md, "Adding a mesh format"). load_mesh
// (mesh_io.hpp) reads a file with the reader of its extension's row, a build hashes the side
// files the row lists (preprocess/build_inputs.hpp), `gfield batch` takes a folder's files of the
// rows marked for it, the helps and errors of the CLI and the Python module list the extensions,
// and tests/fuzz has a reader target per row (tests/geometry/mesh_formats_test.cpp checks it).

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "gfield/confined_path.hpp"

namespace gfield {

struct MeshSoup;
struct ReadFailure;

struct MeshFormat {
  std::string_view extension;  ///< lower case, with its dot: ".obj"
  /// The project's reader of a whole file held in memory (mesh_readers.hpp); null for glTF, read
  /// by load_gltf_mesh (gltf_mesh.hpp).
  bool (*read)(std::string_view data, MeshSoup& soup, ReadFailure& failure);
  /// The files a mesh file names that its appearance reads (mesh_side_files.hpp,
  /// gltf_external_files); null: none.
  std::vector<std::string> (*side_files)(const std::string& mesh_file, OutsidePaths outside);
  /// `gfield batch` takes such files from a folder it is given (glTF files only when named or
  /// listed).
  bool batch;
};

/// Every format, in the order the helps list them.
std::span<const MeshFormat> mesh_formats();

/// The format of `path` by its extension (any case); null when no format has it.
const MeshFormat* find_mesh_format(const std::string& path);

/// The extensions of every format, ".obj, .ply, .off, .stl, .gltf, .glb", for helps and errors.
std::string mesh_extension_list();
/// Those of the formats `gfield batch` takes from a folder.
std::string batch_extension_list();

/// The files mesh file `path` names beside itself (MeshFormat::side_files; none for an unknown
/// extension).
std::vector<std::string> mesh_side_files(const std::string& path, OutsidePaths outside);

}  // namespace gfield
