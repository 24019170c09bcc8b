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
    const bool frames = std::string(argv[i]) == "--frames" && i + 1 < argc;
    const char* text = frames ? argv[++i] : argv[i];
    char* end = nullptr;
    const long value = std::strtol(text, &end, 10);
    if (frames)
      arguments.frames = int(value);
    else
      arguments.sizes.push_back(int(value));
    if (end == text || *end != 0 || value <= 0 || value > 100000) {
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
