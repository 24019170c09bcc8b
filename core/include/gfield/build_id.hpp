#pragma once
// Build ids: the files of one asset build (geometry image, parameterised mesh, geometry field,
// report) carry one id, a hash of the build's inputs, so that a reader can tell a consistent set
// from files of two builds (docs/formats.md, "Build id"). An empty id is a file written before
// build ids existed (format version 1 without the attribute): a set of such files still loads.

#include <string>

namespace gfield {

/// Header attribute (EXR) and comment key (parameterised mesh) that carry the id.
inline constexpr const char* kBuildIdAttribute = "gfield.buildId";

/// True when `id` (of `file`) equals `other_id` (of `other_file`), empty ids included. Otherwise
/// false with an error naming both files and both ids.
bool check_same_build(const std::string& file, const std::string& id, const std::string& other_file,
                      const std::string& other_id, std::string& error);

/// "build id ID", or "no build id" for an empty one.
std::string describe_build_id(const std::string& id);

}  // namespace gfield
