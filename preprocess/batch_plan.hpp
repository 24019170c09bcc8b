#pragma once
// What a `gfield batch` task builds: the meshes of its inputs, their asset names in the output
// folder, and its shard of them (docs/scale-out.md). Every check here runs before anything is
// written, so that bad input leaves nothing behind.

#include <string>
#include <vector>

namespace gfield {

/// Task `index` of `count` (--shard I/N): mesh k of the whole list goes to shard k mod N.
struct Shard {
  int index = 0;
  int count = 1;
};

/// Parses "I/N" with N >= 1 and 0 <= I < N. False with a one-line error otherwise.
bool parse_shard(const std::string& text, Shard& shard, std::string& error);

/// "I/N".
std::string shard_label(const Shard& shard);

/// One mesh of a batch and the asset it builds.
struct BatchMesh {
  std::string mesh;   ///< the mesh file, as listed
  std::string asset;  ///< DIR/<mesh stem>
};

/// The meshes of `inputs` with their assets in `dir`: a folder gives its mesh files (sorted, not
/// recursive, no *.gimage.obj; entries named like meshes that are not readable files, such as
/// symbolic link loops and FIFOs, go to `skipped` as "PATH: why"), a .txt file one path per line
/// (blank lines and # comments skipped, relative to the list), anything else is taken as a mesh
/// file. Duplicates (the same path twice) are kept once. False with an error for a missing
/// input, an unreadable list, no meshes at all, or two meshes that would build the same asset.
bool collect_batch(const std::vector<std::string>& inputs, const std::string& dir,
                   std::vector<BatchMesh>& meshes, std::vector<std::string>& skipped,
                   std::string& error);

/// The meshes of `shard`, in order.
std::vector<BatchMesh> shard_meshes(const std::vector<BatchMesh>& meshes, const Shard& shard);

/// Makes `dir` if needed and checks that files can be created in it (creating and removing a
/// probe file). False with an error naming the folder otherwise.
bool prepare_output_folder(const std::string& dir, std::string& error);

}  // namespace gfield
