#include "gfield/build_id.hpp"

namespace gfield {

std::string describe_build_id(const std::string& id) {
  return id.empty() ? "no build id" : "build id " + id;
}

bool check_same_build(const std::string& file, const std::string& id, const std::string& other_file,
                      const std::string& other_id, std::string& error) {
  if (id == other_id) {
    return true;
  }
  error = file + ": " + describe_build_id(id) + ", but " + other_file + " has " +
          describe_build_id(other_id) + " (files of two different builds; rebuild the asset)";
  return false;
}

}  // namespace gfield
