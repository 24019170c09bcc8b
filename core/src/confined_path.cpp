#include "gfield/confined_path.hpp"

#include <algorithm>

namespace gfield {
namespace fs = std::filesystem;
namespace {

/// True when canonical `path` is `folder` or below it (whole components compared).
bool is_inside(const fs::path& folder, const fs::path& path) {
  const auto [f, p] = std::mismatch(folder.begin(), folder.end(), path.begin(), path.end());
  return f == folder.end() || (std::next(f) == folder.end() && f->empty());
}

}  // namespace

bool path_is_inside(const fs::path& folder, const fs::path& path) {
  std::error_code ec, folder_ec;
  const fs::path target = fs::weakly_canonical(fs::absolute(path, ec), ec);
  const fs::path canonical = fs::weakly_canonical(fs::absolute(folder, folder_ec), folder_ec);
  return !ec && !folder_ec && is_inside(canonical, target);
}

fs::path scene_root(const std::string& scene_file) {
  std::error_code ec;
  const fs::path folder = fs::weakly_canonical(fs::absolute(scene_file, ec).parent_path(), ec);
  for (fs::path p = folder; !p.empty(); p = p.parent_path()) {
    if (fs::is_regular_file(p / kPathRootMarker, ec))
      return p;
    if (p == p.root_path())
      break;
  }
  return folder;
}

bool resolve_named_path(const fs::path& base, const std::string& name, const fs::path& root,
                        OutsidePaths outside, std::string& resolved, std::string& problem,
                        bool root_by_marker) {
  const fs::path path(name);
  resolved = (path.is_absolute() ? path : base / path).lexically_normal().string();
  if (outside == OutsidePaths::kAllowed)
    return true;
  const std::string hint = " (--allow-outside-paths reads it)";
  if (path.is_absolute()) {
    problem = "\"" + name + "\" is an absolute path" + hint;
    return false;
  }
  std::error_code ec, root_ec;
  const fs::path target = fs::weakly_canonical(fs::absolute(resolved, ec), ec);
  // A bare file name's folder is the working folder: "" would resolve to nothing, which holds
  // every path.
  const fs::path folder =
      fs::weakly_canonical(fs::absolute(root.empty() ? fs::path(".") : root, root_ec), root_ec);
  if (ec || root_ec) {
    problem = "\"" + name + "\" cannot be resolved: " + (ec ? ec : root_ec).message();
    return false;
  }
  if (!is_inside(folder, target)) {
    problem = "\"" + name + "\" leaves " + folder.string();
    problem += root_by_marker ? std::string(" (a ") + kPathRootMarker +
                                    " file in a folder above both makes that folder the scene's "
                                    "root; --allow-outside-paths reads it)"
                              : hint;
    return false;
  }
  return true;
}

}  // namespace gfield
