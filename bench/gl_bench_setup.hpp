#pragma once
// What the OpenGL benchmarks of the example scenes share: their arguments `[--frames F]
// [SIZE...]` and the headless context, announced with the GL renderer it runs on.

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "runtime/gl_context.hpp"

namespace gfield {

struct GlBenchArguments {
  std::vector<int> sizes;  ///< square picture sizes, pixels (default 512 1024)
  int frames = 0;          ///< timed frames per row; 0: the benchmark's own default
};

/// Parses `[--frames F] [SIZE...]`; false (with the usage line on stderr) on anything else.
inline bool parse_gl_bench_arguments(int argc, char** argv, const char* name,
                                     GlBenchArguments& arguments) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    char* end = nullptr;
    if (arg == "--frames" && i + 1 < argc) {
      arguments.frames = int(std::strtol(argv[++i], &end, 10));
      if (*end != 0 || arguments.frames <= 0)
        arguments.frames = -1;
    } else {
      arguments.sizes.push_back(int(std::strtol(arg.c_str(), &end, 10)));
      if (*end != 0 || arguments.sizes.back() <= 0)
        arguments.frames = -1;
    }
    if (arguments.frames < 0) {
      std::fprintf(stderr, "usage: %s [--frames F] [SIZE...]   (default sizes 512 1024)\n", name);
      return false;
    }
  }
  if (arguments.sizes.empty())
    arguments.sizes = {512, 1024};
  return true;
}

/// The headless context, its renderer printed on stdout; null (with the reason on stderr) when
/// there is no OpenGL 4.5.
inline std::unique_ptr<GlContext> create_bench_context() {
  std::string error;
  auto context = GlContext::create_headless(error);
  if (!context) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return nullptr;
  }
  std::printf("GL: %s, %s (%s)\n", context->renderer().c_str(), context->version().c_str(),
              context->platform().c_str());
  return context;
}

}  // namespace gfield
