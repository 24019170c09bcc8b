#pragma once
// `gfield build` run as its own process by the build benchmarks: its report and its peak
// resident memory (wait4), so each build is measured as a user would run it.

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "test_support/build_paths.hpp"

namespace gfield {

/// One `gfield build MESH -o NAME --json [OPTIONS...]`: its report and peak resident megabytes;
/// false (with a message) when it fails.
inline bool run_build(const std::string& mesh, const std::string& name,
                      const std::vector<std::string>& options, nlohmann::json& report,
                      double& peak_mb) {
  const std::string out = name + ".stdout";
  std::vector<std::string> args = {gfield::build_paths::cli(), "build", mesh, "-o", name, "--json"};
  args.insert(args.end(), options.begin(), options.end());
  std::vector<char*> argv;
  for (std::string& a : args)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(stdout);  // the child must not write this process's buffered lines again
  const pid_t pid = fork();
  if (pid == 0) {
    std::FILE* file = std::freopen(out.c_str(), "w", stdout);
    if (file == nullptr)
      _exit(127);
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  if (pid < 0 || wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status) ||
      WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "gfield build %s failed\n", mesh.c_str());
    return false;
  }
  peak_mb = double(usage.ru_maxrss) / 1024.0;
  std::ifstream text(out);
  report = nlohmann::json::parse(text, nullptr, false);
  return report.is_object();
}

}  // namespace gfield
