#pragma once
// Which build of an asset its files name now (docs/formats.md, "Publishing"): readers compare it
// before and after a read, and read again when a republish came between.

#include <string>

namespace gfield {

/// The folder the published files of asset `name` (DIR/NAME, no extension) lie in, as
/// NAME.builds/current names it; "" for an asset of plain files or none. It changes when the
/// asset is republished.
std::string published_build(const std::string& name);

/// DIR/NAME of an asset file DIR/NAME.gimage.exr or DIR/NAME.gfield.exr; "" for any other name.
std::string asset_name_of(const std::string& file);

}  // namespace gfield
