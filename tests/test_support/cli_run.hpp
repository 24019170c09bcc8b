#pragma once
// Runs the built executables (`gfield`: GFIELD_CLI; `gfield-view`: GFIELD_VIEW in the runtime
// tests) for end-to-end tests: exit code, stdout, stderr.

#include <sys/wait.h>

#include <unistd.h>
#include <array>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

namespace gfield::test {

struct CliRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

/// Runs `EXECUTABLE ARGS` through the shell (ARGS is shell syntax).
inline CliRun run_program(const std::string& executable, const std::string& args) {
  const std::string err_path =
      std::string(GFIELD_TEST_TMP) + "/cli_stderr_" + std::to_string(::getpid()) + ".txt";
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
  return run_program(GFIELD_CLI, args);
}

}  // namespace gfield::test
