// Wavefront material libraries (.mtl) of an OBJ file: `newmtl NAME`, `Kd r [g b]` (the diffuse
// colour, linear) and `map_Kd [options] FILE` (its texture; the last word names the file,
// relative to the library). Other statements are skipped.

#include <filesystem>
#include <map>

#include "geometry/mesh_readers.hpp"
#include "geometry/text_scan.hpp"
#include "gfield/file_read.hpp"
#include "gfield/limits.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

/// What one library defines: per material name, its colour and texture file ("": none).
struct LibraryMaterial {
  glm::vec3 color{1.0f};
  std::string texture;
};
using Library = std::map<std::string, LibraryMaterial, std::less<>>;

/// The rest of `line` after its first word, without trailing spaces.
std::string_view rest_of_line(std::string_view line, std::string_view first) {
  std::string_view rest = line.substr(size_t(first.data() - line.data()) + first.size());
  while (!rest.empty() && text::is_space(rest.front())) {
    rest.remove_prefix(1);
  }
  while (!rest.empty() && text::is_space(rest.back())) {
    rest.remove_suffix(1);
  }
  return rest;
}

bool read_kd(text::Words& words, glm::vec3& color, std::string& what) {
  double v[3];
  int count = 0;
  std::string_view word;
  while (words.next(word)) {
    if (count == 3 || !text::parse_double(word, v[count]) ||
        !(v[count] >= 0.0 && v[count] <= kMaxColorComponent)) {
      what = "Kd " + text::quoted(word) + " is not a colour component in [0, 1e6]";
      return false;
    }
    ++count;
  }
  if (count != 1 && count != 3) {
    what = "Kd needs 1 or 3 numbers";
    return false;
  }
  color = count == 1 ? glm::vec3(float(v[0])) : glm::vec3(float(v[0]), float(v[1]), float(v[2]));
  return true;
}

/// Where a library's maps may lie: resolved against the library's folder, inside `root` (the
/// OBJ file's folder) unless `outside` is kAllowed.
struct MapPaths {
  fs::path folder, root;
  OutsidePaths outside = OutsidePaths::kRefused;
};

/// Parses library `data`; textures are resolved as `paths` say.
bool parse_library(std::string_view data, const MapPaths& paths, Library& library,
                   ReadFailure& failure) {
  text::Lines lines(data);
  std::string_view line;
  LibraryMaterial* current = nullptr;
  while (lines.next(line)) {
    failure.line = lines.number();
    text::Words words(line);
    std::string_view first, word;
    if (!words.next(first)) {
      continue;
    }
    if (first == "newmtl") {
      if (library.size() >= kMaxMeshMaterials) {
        failure.what = "more than " + std::to_string(kMaxMeshMaterials) + " materials";
        return false;
      }
      current = &library[std::string(rest_of_line(line, first))];
    } else if ((first == "Kd" || first == "map_Kd") && current == nullptr) {
      failure.what = std::string(first) + " before any newmtl";
      return false;
    } else if (first == "Kd" && !read_kd(words, current->color, failure.what)) {
      return false;
    } else if (first == "map_Kd") {
      std::string_view file;
      while (words.next(word)) {
        file = word;
      }
      if (file.empty()) {
        failure.what = "map_Kd without a file";
        return false;
      }
      std::string problem;
      if (!resolve_named_path(paths.folder, std::string(file), paths.root, paths.outside,
                              current->texture, problem)) {
        failure.what = "map_Kd " + problem;
        return false;
      }
    }
  }
  failure.line = 0;
  return true;
}

}  // namespace

bool read_material_libraries(const std::string& obj, OutsidePaths outside, MeshSoup& soup,
                             std::vector<std::string>& warnings, std::string& error) {
  Library library;
  const fs::path folder = fs::path(obj).parent_path();
  for (const std::string& name : soup.libraries) {
    std::string resolved, problem;
    if (!resolve_named_path(folder, name, folder, outside, resolved, problem)) {
      error = obj + ": mtllib " + problem;
      return false;
    }
    const fs::path path = resolved;
    std::string data;
    std::error_code ec;
    if (!fs::is_regular_file(path, ec) ||
        !read_file(path.string(), kMaxMaterialLibraryBytes, data, error)) {
      warnings.push_back(obj + ": material library " + path.string() + ": " +
                         (fs::exists(path, ec) ? error : "no such file") + "; white materials");
      error.clear();
      continue;
    }
    ReadFailure failure;
    if (!parse_library(data, {path.parent_path(), folder, outside}, library, failure)) {
      error = obj + ": material library " + path.string() +
              (failure.line > 0 ? ":" + std::to_string(failure.line) : "") + ": " + failure.what;
      return false;
    }
  }
  std::map<std::string, int> textures;
  for (BaseColorMaterial& material : soup.materials) {
    const auto found = library.find(material.name);
    if (found == library.end()) {
      warnings.push_back(obj + ": material " + text::quoted(material.name) +
                         " is not in its material libraries; white");
      continue;
    }
    material.factor = found->second.color;
    if (found->second.texture.empty()) {
      continue;
    }
    const auto [it, added] = textures.emplace(found->second.texture, int(textures.size()));
    if (added && textures.size() > kMaxMeshTextures) {
      error = obj + ": more than " + std::to_string(kMaxMeshTextures) + " textures";
      return false;
    }
    if (added) {
      soup.texture_files.push_back(found->second.texture);
    }
    material.texture = it->second;
  }
  return true;
}

}  // namespace gfield
