#pragma once
// The scene gfield-view shows: a JSON or glTF scene file (geometry/scene_file.hpp) whose glTF
// meshes get their assets on demand. gfield-view links neither CGAL nor Embree, so it runs
// `gfield assets SCENE [--assets DIR]` (preprocess/cli/assets.cpp): that builds what is missing
// or out of date (the build-id rule of gfield batch) and leaves the rest; the scene is then read
// again with the assets found.

#include <string>
#include <vector>

#include "gfield/scene.hpp"

namespace gfield {

/// The gfield executable gfield-view runs: $GFIELD_CLI, else `gfield` beside gfield-view's own
/// executable, else the build tree's, else "gfield" (found on the PATH).
std::string gfield_executable();

/// Reads `filename` into `scene`, printing its warnings on stderr ("gfield-view: warning: ...");
/// files outside the scene's root (or a glTF file's folder) only when `outside` is kAllowed
/// (--allow-outside-paths, passed on to `gfield assets`). When it holds glTF meshes, runs
/// `gfield assets` first (its output goes to stderr). With `asset_dir`, the assets found there
/// are used (use_asset_folder). Every mesh's asset must have been built from the mesh as it is
/// now (check_scene_assets); with `rebuild_stale`, one built from another mesh (or an older
/// version of it) is rebuilt with `gfield build MESH -o NAME` (default options), else refused.
/// False with a one-line error.
bool load_view_scene(const std::string& filename, const std::string& asset_dir,
                     OutsidePaths outside, bool rebuild_stale, Scene& scene, std::string& error);

/// Makes the thickness maps (NAME.thickness.exr, d_n of Wyman 2005) that the wyman2005 method
/// reads for the meshes of the dielectric objects of `scene`, as the other assets are made on
/// demand: for each such mesh with a geometry image (NAME.gimage.exr) whose map is missing or
/// older than the image, runs `gfield thickness NAME` (its output goes to stderr). False with a
/// one-line error naming the map when one cannot be made.
bool build_thickness_maps(const Scene& scene, std::string& error);

}  // namespace gfield
