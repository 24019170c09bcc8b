#pragma once
// Where the files that an input names may lie (docs/scenes.md, "Confined paths"): a glTF file's
// buffers and images inside the glTF file's folder; a mesh file's material libraries and textures
// inside the mesh file's folder; the files of a JSON scene (meshes, assets, environment images,
// glTF files) inside the scene's root: the nearest folder, from the scene file's own upwards,
// that holds a kPathRootMarker file, else the scene file's own folder. Paths are compared
// canonically (symlinks followed), so a link inside the folder that points out of it leaves it
// too. `--allow-outside-paths` (OutsidePaths::kAllowed) lifts the rule.

#include <filesystem>
#include <string>

namespace gfield {

/// Whether an input may name files outside its folder (or its scene root).
enum class OutsidePaths {
  kRefused,  ///< the default: one line naming the file, the place and the path, exit code 2
  kAllowed,  ///< --allow-outside-paths
};

/// The file whose presence in a folder makes it the root of the JSON scenes below it
/// (data/.gfield-root: the example scenes in data/scenes name meshes in data/meshes).
inline constexpr const char* kPathRootMarker = ".gfield-root";

/// True when `path` is `folder` or lies below it, both compared canonically (symlinks followed;
/// false when either cannot be resolved).
bool path_is_inside(const std::filesystem::path& folder, const std::filesystem::path& path);

/// The root of JSON scene file `scene_file` (see above), canonical.
std::filesystem::path scene_root(const std::string& scene_file);

/// Resolves `name`, a path a file in folder `base` names, to `resolved` (base / name, lexically
/// normal; `name` itself when absolute). Unless `outside` is kAllowed, an absolute `name` and one
/// whose canonical path is not inside the canonical `root` are refused: false with `problem`
/// saying why ("is an absolute path", "leaves ROOT"), without touching the file. With
/// `root_by_marker` (a JSON scene's root: scene_root) the message of a path that leaves the root
/// names the kPathRootMarker file that would move it.
bool resolve_named_path(const std::filesystem::path& base, const std::string& name,
                        const std::filesystem::path& root, OutsidePaths outside,
                        std::string& resolved, std::string& problem, bool root_by_marker = false);

}  // namespace gfield
