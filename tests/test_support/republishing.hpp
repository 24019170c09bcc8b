#pragma once
// Readers run while an asset is republished, for the tests that an asset's reader sees one build
// (docs/formats.md, "Publishing"): `publish(round)` republishes on a thread of its own, a given
// number of rounds, and the reads go on until the last round is published. The count is of
// publications, the events under test, not of reads: a read costs more than a publication on one
// machine (a viewer's start) and less on another (an instrumented build).

#include <atomic>
#include <functional>
#include <string>
#include <thread>

#include "test_support/cli_run.hpp"

namespace gfield::test {

/// Runs `read` again and again while `publish(round)` (round 1 .. `rounds`) republishes the
/// asset, at least once and until the last round is done; the reads that failed (exit code not
/// 0), the last one's stderr in `failure`.
inline int failed_reads_while_republishing(const std::function<void(int)>& publish,
                                           const std::function<CliRun()>& read, int rounds,
                                           std::string& failure) {
  std::atomic<bool> done{false};
  std::thread publisher([&] {
    for (int round = 1; round <= rounds; ++round)
      publish(round);
    done = true;
  });
  int failed = 0;
  do {
    const CliRun r = read();
    if (r.exit_code != 0) {
      ++failed;
      failure = r.err;
    }
  } while (!done);
  publisher.join();
  return failed;
}

}  // namespace gfield::test
