// Every test program joins TBB's worker threads after its last test (WorkerThreads), before the
// process exits.

#include <gtest/gtest.h>

#include <optional>

#include "preprocess/worker_threads.hpp"

namespace {

class JoinWorkerThreads : public ::testing::Environment {
 public:
  void SetUp() override { workers_.emplace(); }
  void TearDown() override { workers_.reset(); }

 private:
  std::optional<gfield::WorkerThreads> workers_;
};

const ::testing::Environment* const kJoinWorkerThreads =
    ::testing::AddGlobalTestEnvironment(new JoinWorkerThreads);

}  // namespace
