// gfield batch INPUT... -o DIR: `gfield build` over folders, mesh files and lists of meshes, as
// one task of a sharded batch (--shard I/N), resumable (assets whose files carry the build id of
// their current inputs are skipped), with a manifest per task; --summary DIR merges the
// manifests (docs/scale-out.md).

#include <unistd.h>
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "gfield/printable.hpp"
#include "preprocess/asset_files.hpp"
#include "preprocess/asset_staging.hpp"
#include "preprocess/batch_manifest.hpp"
#include "preprocess/batch_summary.hpp"
#include "preprocess/cli/asset_options.hpp"
#include "preprocess/cli/commands.hpp"
#include "preprocess/thread_limit.hpp"

namespace gfield {
namespace {

struct BatchArguments {
  std::vector<std::string> inputs;
  std::string dir;
  std::string shard;
  std::string summary;
  int threads = 0;
  bool force = false;
  bool list = false;
  AssetArguments asset;
};

/// What every manifest line of this task shares.
struct TaskContext {
  Shard shard;
  size_t shard_meshes = 0;
  size_t meshes = 0;
  std::string host;
};

void print_progress(size_t done, size_t total, const std::string& what) {
  constexpr int kWidth = 30;
  const int filled = total == 0 ? kWidth : int(kWidth * done / total);
  std::fprintf(stderr, "[%s%s] %zu/%zu %s\n", std::string(size_t(filled), '#').c_str(),
               std::string(size_t(kWidth - filled), '.').c_str(), done, total,
               printable(what).c_str());
}

std::string host_name() {
  char name[256] = {};
  return ::gethostname(name, sizeof(name) - 1) == 0 ? name : "";
}

/// Builds (or skips, when up to date) one mesh; returns its manifest line.
nlohmann::json run_mesh(const BatchMesh& m, const AssetOptions& options, bool force,
                        const TaskContext& task) {
  const auto started = std::chrono::system_clock::now();
  nlohmann::json record = {{"mesh", printable(m.mesh)},
                           {"asset", printable(m.asset)},
                           {"shard", shard_label(task.shard)},
                           {"shard_index", task.shard.index},
                           {"shard_count", task.shard.count},
                           {"shard_meshes", task.shard_meshes},
                           {"meshes", task.meshes},
                           {"host", task.host},
                           {"pid", ::getpid()},
                           {"started", utc_timestamp(started)}};
  BuildInputs inputs;
  AssetReport report;
  std::string error;
  std::string why;
  bool ok = false;
  try {
    ok = asset_build_inputs(m.mesh, options, inputs, error);
    if (ok && !force && asset_is_build(asset_files(m.asset), inputs.build_id, why)) {
      record["status"] = "up to date";
    } else if (ok) {
      ok = build_asset(m.mesh, m.asset, options, inputs, report, error);
      record["status"] = ok ? "built" : "failed";
    }
  } catch (const std::exception& e) {
    ok = false;
    error = m.mesh + ": " + e.what();
  }
  const auto finished = std::chrono::system_clock::now();
  record["finished"] = utc_timestamp(finished);
  record["seconds"] = std::chrono::duration<double>(finished - started).count();
  record["build_id"] = inputs.build_id;
  if (!ok) {
    record["status"] = "failed";
    record["error"] = printable(error);
    return record;
  }
  const AssetFiles files = asset_files(m.asset);
  record["outputs"] = {printable(files.image), printable(files.parameterized_mesh),
                       printable(files.field), printable(files.report)};
  record["accuracy"] = manifest_accuracy(report);
  if (record["status"] == "built") {
    record["summary"] = asset_summary(report);
  }
  return record;
}

/// --list: the task's meshes and whether each is up to date; writes nothing.
void list_meshes(const std::vector<BatchMesh>& meshes, const AssetOptions& options, bool force) {
  for (const BatchMesh& m : meshes) {
    BuildInputs inputs;
    std::string why;
    const std::string mesh = printable(m.mesh), asset = printable(m.asset);
    if (!asset_build_inputs(m.mesh, options, inputs, why)) {
      std::printf("%s -> %s: fails (%s)\n", mesh.c_str(), asset.c_str(), printable(why).c_str());
    } else if (!force && asset_is_build(asset_files(m.asset), inputs.build_id, why)) {
      std::printf("%s -> %s: up to date (build %s)\n", mesh.c_str(), asset.c_str(),
                  inputs.build_id.c_str());
    } else {
      std::printf("%s -> %s: to build (%s)\n", mesh.c_str(), asset.c_str(),
                  force ? "--force" : printable(why).c_str());
    }
  }
}

/// Prints the line of one finished mesh.
void print_result(const nlohmann::json& record) {
  const std::string mesh = record["mesh"].get<std::string>();
  const std::string status = record["status"].get<std::string>();
  if (status == "failed") {
    std::printf("%s: FAILED: %s\n", mesh.c_str(), record["error"].get<std::string>().c_str());
  } else if (status == "up to date") {
    std::printf("%s: up to date (%s.*, build %s)\n", mesh.c_str(),
                record["asset"].get<std::string>().c_str(),
                record["build_id"].get<std::string>().c_str());
  } else {
    std::printf("%s: %s (%.1f s)\n", mesh.c_str(), record["summary"].get<std::string>().c_str(),
                record["seconds"].get<double>());
  }
  std::fflush(stdout);
}

void run_batch(const BatchArguments& args) {
  std::string error;
  Shard shard;
  std::vector<BatchMesh> all;
  if (args.inputs.empty() || args.dir.empty()) {
    throw CommandError("batch: needs INPUT... and -o DIR (or --summary DIR)");
  }
  std::vector<std::string> skipped;
  if ((!args.shard.empty() && !parse_shard(args.shard, shard, error)) ||
      !collect_batch(args.inputs, args.dir, all, skipped, error)) {
    throw CommandError(error);
  }
  for (const std::string& entry : skipped)
    std::fprintf(stderr, "gfield: warning: skipped %s\n", printable(entry).c_str());
  const std::vector<BatchMesh> meshes = shard_meshes(all, shard);
  const AssetOptions options = asset_options(args.asset);
  const ThreadLimit threads(args.threads);
  if (args.list) {
    list_meshes(meshes, options, args.force);
    return;
  }
  if (!prepare_output_folder(args.dir, error)) {
    throw CommandError(error);
  }
  if (const size_t stale = remove_stale_staging(args.dir); stale > 0) {
    std::printf("batch: removed %zu build folders of killed builds in %s\n", stale,
                printable(args.dir).c_str());
  }
  const TaskContext task{shard, meshes.size(), all.size(), host_name()};
  const std::string manifest = manifest_path(args.dir, shard);
  std::vector<std::string> failed;
  size_t built = 0;
  for (size_t i = 0; i < meshes.size(); ++i) {
    print_progress(i, meshes.size(), meshes[i].mesh);
    const nlohmann::json record = run_mesh(meshes[i], options, args.force, task);
    print_result(record);
    if (!append_manifest_line(manifest, record, error)) {
      throw CommandError(error);
    }
    built += record["status"] == "built" ? 1 : 0;
    if (record["status"] == "failed") {
      failed.push_back(meshes[i].mesh);
    }
  }
  print_progress(meshes.size(), meshes.size(), "done");
  std::printf("batch %s: %zu built, %zu up to date, %zu failed; manifest %s\n",
              shard_label(shard).c_str(), built, meshes.size() - built - failed.size(),
              failed.size(), printable(manifest).c_str());
  if (!failed.empty()) {
    std::string list;
    for (const std::string& f : failed) {
      list += (list.empty() ? "" : ", ") + f;
    }
    throw CommandError("batch: " + std::to_string(failed.size()) + " of " +
                       std::to_string(meshes.size()) + " meshes failed: " + list);
  }
}

void run_summary(const std::string& dir) {
  BatchSummary summary;
  std::string error;
  if (!summarize_batch(dir, summary, error)) {
    throw CommandError(error);
  }
  std::printf("%s", summary.text.c_str());
  if (summary.shards_to_rerun.empty()) {
    return;
  }
  std::string shards;
  for (const int s : summary.shards_to_rerun) {
    shards += (shards.empty() ? "" : ",") + std::to_string(s);
  }
  const std::string n = std::to_string(summary.shard_count);
  std::printf(
      "rerun shards %s of %s: sbatch --array=%s --export=ALL,GFIELD_SHARDS=%s "
      "scripts/slurm/gfield-batch.sbatch INPUT... -o %s (or gfield batch INPUT... -o %s "
      "--shard I/%s for each)\n",
      shards.c_str(), n.c_str(), shards.c_str(), n.c_str(), dir.c_str(), dir.c_str(), n.c_str());
  std::fflush(stdout);
  throw CommandError("batch " + dir + ": " + std::to_string(summary.failed) + " failed, " +
                     std::to_string(summary.missing) + " without a line, of " +
                     std::to_string(summary.meshes) + " meshes");
}

}  // namespace

void add_batch_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "batch",
      "Run `gfield build` for every mesh of the inputs (folders of meshes, mesh files, or .txt\n"
      "lists with one mesh path per line) into DIR/<mesh name>.*, or for shard I of N of them\n"
      "(--shard I/N: mesh k goes to shard k mod N). Skips meshes whose four files carry the\n"
      "build id of their current inputs (mesh and texture contents, options; unless --force),\n"
      "keeps going past meshes that fail, appends one line per mesh to\n"
      "DIR/manifest-I-of-N.jsonl, and exits with an error listing the failed meshes at the end.\n"
      "--summary DIR merges the manifests of all tasks into one table.");
  auto args = std::make_shared<BatchArguments>();
  cmd->add_option("INPUT", args->inputs,
                  "folders (their " + batch_extension_list() + " files), mesh files or .txt lists");
  cmd->add_option("-o,--output", args->dir, "output folder");
  cmd->add_option("--shard", args->shard, "build only shard I of N (0 <= I < N), e.g. 2/8");
  cmd->add_option("--threads", args->threads, "threads of this task (0: all cores)")
      ->check(CLI::Range(0, 4096))
      ->capture_default_str();
  cmd->add_flag("--force", args->force, "rebuild outputs that are up to date");
  cmd->add_flag("--list", args->list,
                "print this task's meshes and whether each is up to date; build nothing");
  cmd->add_option("--summary", args->summary,
                  "merge DIR's manifests into one table; exit code 2 if any mesh failed or has "
                  "no line");
  add_asset_options(cmd, std::shared_ptr<AssetArguments>(args, &args->asset));
  cmd->callback([args] {
    if (!args->summary.empty()) {
      run_summary(args->summary);
    } else {
      run_batch(*args);
    }
  });
}

}  // namespace gfield
