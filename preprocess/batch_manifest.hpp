#pragma once
// The manifest of a `gfield batch` task (docs/scale-out.md): DIR/manifest-I-of-N.jsonl, one JSON
// object per line and mesh, appended as each mesh ends (a killed task keeps the lines of the
// meshes it finished; a resubmitted one appends, and the later line wins):
//
//   {"mesh", "asset", "status": "built" | "up to date" | "failed", "error" (failed only),
//    "build_id", "shard": "I/N", "shard_index", "shard_count", "shard_meshes", "meshes" (whole
//    batch), "started", "finished"
//    (UTC, ISO 8601), "seconds", "host", "pid", "accuracy" (built only: "table_hit_miss",
//    "refined_hit_miss", "refined_median_percent", "refined_p95_percent"), "outputs"}

#include <chrono>
#include <string>

#include <nlohmann/json.hpp>

#include "preprocess/asset_report.hpp"
#include "preprocess/batch_plan.hpp"

namespace gfield {

/// DIR/manifest-I-of-N.jsonl.
std::string manifest_path(const std::string& dir, const Shard& shard);

/// `time` as UTC ISO 8601 with milliseconds: 2026-11-23T14:03:05.123Z.
std::string utc_timestamp(std::chrono::system_clock::time_point time);

/// The accuracy figures of a build report kept in the manifest (empty object without any).
nlohmann::json manifest_accuracy(const AssetReport& report);

/// Appends `record` as one line to `path` in a single write (O_APPEND). False with an error
/// "FILE: problem".
bool append_manifest_line(const std::string& path, const nlohmann::json& record,
                          std::string& error);

}  // namespace gfield
