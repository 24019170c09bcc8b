#pragma once
// `gfield batch --summary DIR`: every task's manifest (batch_manifest.hpp) merged into one table
// (docs/scale-out.md, "Reading the summary"). For each asset the latest line wins (by its
// "finished" time, then by file and line order), so a resubmitted shard's results replace the
// cancelled task's.

#include <string>
#include <vector>

namespace gfield {

struct BatchSummary {
  std::string text;                  ///< the table, counts, slowest meshes, failures
  size_t meshes = 0;                 ///< meshes in the whole batch
  size_t failed = 0;                 ///< assets whose latest line is "failed"
  size_t missing = 0;                ///< meshes of the batch without any line
  int shard_count = 0;               ///< N of the latest line
  std::vector<int> shards_to_rerun;  ///< of N: shards with a failure or fewer lines than meshes
};

/// Reads DIR/manifest-*-of-*.jsonl. False with an error naming DIR when there is none.
/// Unreadable lines (a task killed while writing one) are skipped and listed in the text.
bool summarize_batch(const std::string& dir, BatchSummary& summary, std::string& error);

}  // namespace gfield
