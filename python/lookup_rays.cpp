// gfield_lookup_rays FIELD.gfield.exr IMAGE.gimage.exr RAYS MODE [ANSWERS] [REPEAT]
//
// The C++ CPU lookup (gfield/field_lookup.hpp: lookup_first_hit) of the rays in RAYS, one by one
// in a TBB parallel_for over every core, as a C++ program linking gfield::core calls it: the
// reference of the Python module's GeometryField.lookup. RAYS holds float32 rows of 7 values
// (origin x y z, direction x y z, t_min); MODE is nearest, linear or refined. ANSWERS (optional,
// "-" for none) receives float32 rows of 11 values per ray: hit (0 or 1), t, distance, position
// x y z, normal x y z, uv u v. The lookups run REPEAT times (default 1); it prints the best run's
// seconds and rays per second, and the best run's CPU seconds (all threads of the process: on a
// machine that other work loads, the cost of the lookups less the time they waited for a core).
// Exit code 2 with a message for bad input.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <string>
#include <vector>

#include "gfield/exr_io.hpp"
#include "gfield/field_lookup.hpp"
#include "gfield/stopwatch.hpp"

namespace {

using namespace gfield;

/// CPU seconds of the whole process, all its threads.
double process_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

int fail(const std::string& message) {
  std::fprintf(stderr, "gfield_lookup_rays: %s\n", message.c_str());
  return 2;
}

/// The rays of the file: 7 float32 each.
bool read_rays(const std::string& file, std::vector<Ray>& rays) {
  std::ifstream in(file, std::ios::binary);
  float row[7];
  while (in.read(reinterpret_cast<char*>(row), sizeof(row))) {
    rays.push_back(Ray{{row[0], row[1], row[2]}, {row[3], row[4], row[5]}, row[6]});
  }
  return in.eof() && in.gcount() == 0;
}

bool write_answers(const std::string& file, const std::vector<FieldHit>& hits) {
  std::ofstream out(file, std::ios::binary);
  for (const FieldHit& h : hits) {
    const float row[11] = {h.hit ? 1.0f : 0.0f, h.t,          h.distance, h.position.x,
                           h.position.y,        h.position.z, h.normal.x, h.normal.y,
                           h.normal.z,          h.uv.x,       h.uv.y};
    out.write(reinterpret_cast<const char*>(row), sizeof(row));
  }
  return bool(out);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5 || argc > 7) {
    return fail("usage: gfield_lookup_rays FIELD IMAGE RAYS MODE [ANSWERS|-] [REPEAT]");
  }
  LookupMode mode = LookupMode::kRefined;
  if (!parse_lookup_mode(argv[4], mode)) {
    return fail(std::string("unknown mode ") + argv[4]);
  }
  GeometryField field;
  GeometryImage image;
  FieldLookup lookup;
  std::string error;
  if (!load_geometry_field(argv[1], field, error) || !load_geometry_image(argv[2], image, error) ||
      !make_field_lookup(field, image, lookup, error)) {
    return fail(error);
  }
  std::vector<Ray> rays;
  if (!read_rays(argv[3], rays)) {
    return fail(std::string(argv[3]) + ": not rows of 7 float32");
  }
  const int repeat = argc > 6 ? std::max(1, std::atoi(argv[6])) : 1;
  std::vector<FieldHit> hits(rays.size());
  double best = 1e30;
  double best_cpu = 1e30;
  for (int r = 0; r < repeat; ++r) {
    const double cpu_start = process_cpu_seconds();
    Stopwatch watch;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size()),
                      [&](const tbb::blocked_range<size_t>& range) {
                        for (size_t i = range.begin(); i != range.end(); ++i) {
                          hits[i] = lookup_first_hit(lookup, rays[i], mode);
                        }
                      });
    best = std::min(best, watch.seconds());
    best_cpu = std::min(best_cpu, process_cpu_seconds() - cpu_start);
  }
  if (argc > 5 && std::string(argv[5]) != "-" && !write_answers(argv[5], hits)) {
    return fail(std::string(argv[5]) + ": cannot write");
  }
  std::printf("%zu rays, %s, best of %d: %.4f s, %.3f Mrays/s, cpu %.4f s\n", rays.size(),
              lookup_mode_name(mode), repeat, best, double(rays.size()) / best / 1e6, best_cpu);
  return 0;
}
