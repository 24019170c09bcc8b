#include "gfield/published_build.hpp"

#include <filesystem>

namespace gfield {

std::string published_build(const std::string& name) {
  std::error_code ec;
  return std::filesystem::read_symlink(name + ".builds/current", ec).string();
}

std::string asset_name_of(const std::string& file) {
  for (const std::string suffix : {".gimage.exr", ".gfield.exr"})
    if (file.size() > suffix.size() &&
        file.compare(file.size() - suffix.size(), suffix.size(), suffix) == 0)
      return file.substr(0, file.size() - suffix.size());
  return "";
}

}  // namespace gfield
