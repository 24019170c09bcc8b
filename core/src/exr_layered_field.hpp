#pragma once
// Layered geometry fields (format versions 1 and 2: K tables of (6N^2)^2 uvs), read for the
// compact field's reader (internal to gfield_core: exr_field.cpp).

#include <OpenEXR/ImfInputFile.h>

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gfield/exr_io.hpp"

namespace gfield::exr {

/// A layered field's table (version 1 or 2; `header.layers` tables of (6N^2)^2 uvs, layer by
/// layer) from an open file whose header was checked; its channels, size and values checked.
bool read_layered_table(const std::string& filename, Imf::InputFile& file,
                        const ExrAssetHeader& header, std::vector<glm::vec2>& table,
                        std::string& error);

}  // namespace gfield::exr
