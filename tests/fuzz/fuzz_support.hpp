#pragma once
// What every fuzz target shares: the input written to a file of its own (the loaders under test
// read files, as the tools do), and the loaders' contract checked on every input, so that a
// broken contract is a crash the fuzzer reports and the replay test fails on:
// - a failure gives a non-empty one-line error that starts with the file's name;
// - a success gives data within the documented limits (each target checks its own).

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace gfield::fuzz {

/// Stops the process (a crash to libFuzzer, a failure to the replay test) with `what`.
[[noreturn]] inline void violated(const std::string& what) {
  std::fprintf(stderr, "fuzz contract violated: %s\n", what.c_str());
  std::abort();
}

inline void check(bool condition, const char* what) {
  if (!condition) {
    violated(what);
  }
}

/// A folder of this process under $TMPDIR (or /tmp), removed at exit.
inline const std::filesystem::path& scratch_folder() {
  static const std::filesystem::path folder = [] {
    const char* tmp = std::getenv("TMPDIR");
    std::filesystem::path p = std::filesystem::path(tmp && *tmp ? tmp : "/tmp") /
                              ("gfield-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(p);
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(scratch_folder(), ec);
    });
    return p;
  }();
  return folder;
}

/// Writes the input to SCRATCH/NAME and returns its path.
inline std::string write_input(const std::uint8_t* data, size_t size, const std::string& name) {
  const std::string path = (scratch_folder() / name).string();
  // A new file each time: truncating the old one makes ext4 flush it to disk (auto_da_alloc),
  // which would slow the fuzzer down tenfold.
  std::filesystem::remove(path);
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  check(bool(out), "cannot write the input file");
  return path;
}

/// The error contract: non-empty, one line, starting with the file's name.
inline void check_error(const std::string& filename, const std::string& error) {
  if (error.rfind(filename, 0) != 0 || error.size() == filename.size() ||
      error.find('\n') != std::string::npos) {
    violated("error does not name the file on one line: " + error);
  }
}

}  // namespace gfield::fuzz
