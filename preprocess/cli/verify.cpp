// gfield verify NAME: accuracy of NAME.gfield.exr + NAME.gimage.exr against exact Embree casts.

#include <CLI/CLI.hpp>

#include <cstdio>
#include <nlohmann/json.hpp>

#include "preprocess/cli/commands.hpp"
#include "preprocess/cli/path_options.hpp"
#include "preprocess/verify.hpp"

namespace gfield {

void add_verify_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "verify",
      "Check the asset NAME (NAME.gfield.exr, NAME.gimage.exr, NAME.gimage.obj) against exact\n"
      "Embree casts on the mesh it was built from and on the original mesh file: the stored\n"
      "table (random sample pairs) and every lookup mode (nearest, linear, refined, refined\n"
      "last hit) on random rays between box faces and from outside viewpoints, and on rays\n"
      "leaving the surface (random points and directions, mirror reflections of view rays;\n"
      "1e-4 of the diagonal off it, looked up as the viewer does, past the geometry image's\n"
      "ray offset) with K = 1 and all K layers: hit/miss agreement, position error (median,\n"
      "p95, p99 in % of the box diagonal), normal error.");
  struct Arguments {
    std::string name;
    size_t rays = 1000000;
    uint64_t seed = 1;
    std::string original;
    int field_bits = 32;
    bool json = false;
    bool allow_outside_paths = false;
  };
  auto args = std::make_shared<Arguments>();
  cmd->add_option("NAME", args->name, "asset path without extension (DIR/NAME)")->required();
  cmd->add_option("--rays", args->rays, "random rays per family (and table pairs)")
      ->check(CLI::Range(size_t(1), size_t(100000000)))
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "random seed")->capture_default_str();
  cmd->add_option("--original", args->original,
                  "original mesh file (default: NAME.report.json's source_path, or the source)");
  cmd->add_option("--field-bits", args->field_bits,
                  "look the field up as the GPU stores it: 8 or 16 bits per uv component (32: "
                  "as in the file)")
      ->check(CLI::IsMember({8, 16, 32}))
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "print the report as JSON");
  add_outside_paths_option(cmd, args->allow_outside_paths);
  cmd->callback([args] {
    VerifyOptions options;
    options.rays = args->rays;
    options.seed = args->seed;
    options.original = args->original;
    options.field_bits = args->field_bits;
    options.original_outside_paths = outside_paths(args->allow_outside_paths);
    VerifyReport report;
    std::string error;
    if (!verify_asset(args->name, options, report, error)) {
      throw CommandError(error);
    }
    if (args->json) {
      std::printf("%s\n", verify_report_to_json(report).dump(2).c_str());
    } else {
      std::printf("%s", verify_report_to_text(report).c_str());
    }
  });
}

}  // namespace gfield
