#pragma once
// Runs the built executables (`gfield`: gfield::build_paths::cli(); `gfield-view`:
// gfield::build_paths::view() in the runtime tests) for end-to-end tests: exit code, stdout,
// stderr.

#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>

#include <unistd.h>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <iterator>
#include <string>

#include "test_support/build_paths.hpp"

namespace gfield::test {

struct CliRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

/// Runs `EXECUTABLE ARGS` through the shell (ARGS is shell syntax).
inline CliRun run_program(const std::string& executable, const std::string& args) {
  const std::string err_path = std::string(gfield::build_paths::test_tmp()) + "/cli_stderr_" +
                               std::to_string(::getpid()) + ".txt";
  const std::string command = executable + " " + args + " 2>" + err_path;
  CliRun run;
  FILE* pipe = popen(command.c_str(), "r");
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
    run.out.append(buffer.data(), n);
  }
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(err_path);
  run.err.assign(std::istreambuf_iterator<char>(in), {});
  std::remove(err_path.c_str());
  return run;
}

/// Runs `gfield ARGS`.
inline CliRun run_cli(const std::string& args) {
  return run_program(gfield::build_paths::cli(), args);
}

/// True when `output` exists and is newer than `gfield` itself and every one of `inputs`. CTest
/// runs each test in a process of its own, so a suite's set-up runs once per test: with this it
/// reuses what the set-up of an earlier test of the same build made, and redoes it after a
/// rebuild of the tool or a change of an input.
inline bool up_to_date(const std::string& output, std::initializer_list<std::string> inputs) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_time_type made = fs::last_write_time(output, ec);
  if (ec || fs::last_write_time(gfield::build_paths::cli(), ec) >= made || ec)
    return false;
  for (const std::string& input : inputs) {
    if (fs::last_write_time(input, ec) >= made || ec)
      return false;
  }
  return true;
}

/// Runs `make` unless `output` is up_to_date, holding an exclusive lock on OUTPUT.lock meanwhile:
/// CTest runs a suite's tests in processes of their own, in parallel, and the set-up of a second
/// one waits for the first's output instead of making it again at the same time.
inline void make_unless_up_to_date(const std::string& output,
                                   std::initializer_list<std::string> inputs,
                                   const std::function<void()>& make) {
  const std::string lock = output + ".lock";
  const int fd = open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd >= 0)
    flock(fd, LOCK_EX);  // without the lock file both make it, as without the lock
  if (!up_to_date(output, inputs))
    make();
  if (fd >= 0)
    close(fd);  // releases the lock
}

}  // namespace gfield::test
