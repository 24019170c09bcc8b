#pragma once
// Readers run while an asset is republished, for the tests that an asset's reader sees one build
// (docs/formats.md, "Publishing"): `publish(round)` republishes on a thread of its own, round
// after round, for as long as the reads last.

#include <atomic>
#include <functional>
#include <string>
#include <thread>

#include "test_support/cli_run.hpp"

namespace gfield::test {

/// Runs `read` `reads` times while `publish(round)` (round 1, 2, ...) republishes the asset; the
/// reads that failed (exit code not 0), the last one's stderr in `failure`.
inline int failed_reads_while_republishing(const std::function<void(int)>& publish,
                                           const std::function<CliRun()>& read, int reads,
                                           std::string& failure) {
  std::atomic<bool> done{false};
  std::thread publisher([&] {
    for (int round = 1; !done; ++round)
      publish(round);
  });
  int failed = 0;
  for (int i = 0; i < reads; ++i) {
    const CliRun r = read();
    if (r.exit_code != 0) {
      ++failed;
      failure = r.err;
    }
  }
  done = true;
  publisher.join();
  return failed;
}

}  // namespace gfield::test
