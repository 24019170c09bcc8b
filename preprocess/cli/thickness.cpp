// gfield thickness DIR/NAME: d_n per geometry-image texel (Wyman 2005) -> NAME.thickness.exr.

#include <CLI/CLI.hpp>

#include <cstdio>

#include "preprocess/cli/commands.hpp"
#include "preprocess/thickness.hpp"

namespace gfield {

void add_thickness_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "thickness",
      "Distance along the negative normal to the other side of the object (d_n of Wyman 2005)\n"
      "for every texel of NAME.gimage.exr, cast with Embree against NAME.gimage.obj; writes\n"
      "NAME.thickness.exr (docs/image-space-refraction.md). Needed by gfield-view --method "
      "wyman2005.");
  auto name = std::make_shared<std::string>();
  cmd->add_option("NAME", *name, "asset path without extension (DIR/NAME, as gfield build -o)")
      ->required();
  cmd->callback([name] {
    ThicknessStats stats;
    std::string error;
    if (!write_thickness_file(*name, stats, error))
      throw CommandError(error);
    std::printf("%s.thickness.exr: %zu texels cast, %zu without a far side, %.3f s\n",
                name->c_str(), stats.covered_texels, stats.misses, stats.seconds);
  });
}

}  // namespace gfield
