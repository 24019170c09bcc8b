// Replays inputs through a fuzz target's entry point without libFuzzer (the normal gcc build):
// `fuzz_replay_X PATH...` runs LLVMFuzzerTestOneInput on every file of each PATH (a file or a
// folder, recursively, in name order) and prints how long the slowest took, overall and among
// inputs of at most 1 KB. Exit 0 when all ran; a broken contract aborts (fuzz_support.hpp); an
// input taking longer than --max-seconds S (default 10) fails the run.

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size);

namespace {

std::vector<std::filesystem::path> inputs_of(const std::filesystem::path& path) {
  std::vector<std::filesystem::path> files;
  if (std::filesystem::is_directory(path)) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(path)) {
      if (entry.is_regular_file()) {
        files.push_back(entry.path());
      }
    }
    std::sort(files.begin(), files.end());
  } else {
    files.push_back(path);
  }
  return files;
}

}  // namespace

int main(int argc, char** argv) {
  double max_seconds = 10.0;
  std::vector<std::filesystem::path> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--max-seconds" && i + 1 < argc) {
      max_seconds = std::atof(argv[++i]);
      continue;
    }
    if (!std::filesystem::exists(arg)) {
      std::fprintf(stderr, "fuzz_replay: %s: no such file or folder\n", arg.c_str());
      return 2;
    }
    const std::vector<std::filesystem::path> found = inputs_of(arg);
    files.insert(files.end(), found.begin(), found.end());
  }
  double slowest = 0.0, slowest_small = 0.0;
  std::string slowest_name, slowest_small_name;
  for (const std::filesystem::path& file : files) {
    std::ifstream in(file, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), {});
    const auto start = std::chrono::steady_clock::now();
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (seconds > slowest) {
      slowest = seconds;
      slowest_name = file.string();
    }
    if (bytes.size() <= 1024 && seconds > slowest_small) {
      slowest_small = seconds;
      slowest_small_name = file.string();
    }
  }
  std::printf("replayed %zu inputs; slowest %.4f s (%s); of those <= 1 KB %.4f s (%s)\n",
              files.size(), slowest, slowest_name.c_str(), slowest_small,
              slowest_small_name.c_str());
  if (files.empty() || slowest > max_seconds) {
    std::fprintf(stderr, "fuzz_replay: %s\n",
                 files.empty() ? "no inputs" : "an input took longer than --max-seconds");
    return 1;
  }
  return 0;
}
