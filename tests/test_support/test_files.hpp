#pragma once
// The tests' scratch files: a folder of the process's own under the build's test folder, and
// files written into it with their folders.

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "test_support/build_paths.hpp"

namespace gfield::test {

/// build_paths::test_tmp()/NAME_PID: a folder no other test process writes into (CTest runs
/// tests in parallel, each in a process of its own).
inline std::filesystem::path process_folder(const std::string& name) {
  return std::filesystem::path(gfield::build_paths::test_tmp()) /
         (name + "_" + std::to_string(::getpid()));
}

/// Writes `bytes` to `file` as they are, creating its folders.
inline void write_file(const std::filesystem::path& file, const std::string& bytes) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << bytes;
}

}  // namespace gfield::test
