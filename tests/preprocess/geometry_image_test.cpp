// Geometry images: routes, uv faults, coverage, reconstruction error of the shared
// meshes; the uv contract of NAME.gimage.obj checked against the image through the core bilinear
// lookup; orbifold seamlessness; cut graphs; packing; bad input; determinism; the CLI.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>

#include <nlohmann/json.hpp>

#include "geometry/mesh_io.hpp"
#include "geometry/parameterized_mesh.hpp"
#include "gfield/exr_io.hpp"
#include "gfield/geometry_image.hpp"
#include "preprocess/chart_packing.hpp"
#include "preprocess/cut_graph.hpp"
#include "preprocess/geometry_image_build.hpp"
#include "preprocess/surface_distance.hpp"
#include "preprocess/topology.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/cli_run.hpp"

namespace gfield {
namespace {

struct Built {
  TriangleMesh input;
  GeometryImage image;
  ParameterizedMesh pm;
  GeometryImageReport report;
};

/// Loads data/meshes/NAME and builds its geometry image into `b`; fatal failure when either
/// fails (callers wrap it in ASSERT_NO_FATAL_FAILURE).
void build(const std::string& name, int size, Built& b, bool measure = true, bool split = true) {
  std::string error;
  ASSERT_TRUE(load_mesh(std::string(gfield::build_paths::mesh_dir()) + "/" + name, b.input, error))
      << error;
  GeometryImageOptions options;
  options.size = size;
  options.measure = measure;
  options.split_protrusions = split;
  options.error_samples = 20000;
  ASSERT_TRUE(build_geometry_image(b.input, options, b.image, b.pm, b.report, error))
      << name << ": " << error;
}

double diagonal_of(const std::vector<glm::dvec3>& points) {
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const glm::dvec3& p : points)
    lo = glm::min(lo, p), hi = glm::max(hi, p);
  return glm::length(hi - lo);
}

/// The contract the geometry field relies on: the image at the uv interpolated from a face's
/// corner uvs returns the point of the face (distance in % of the diagonal, 95th percentile).
double uv_contract_p95(const Built& b) {
  std::vector<double> distance;
  const double diagonal = diagonal_of(b.pm.mesh.positions);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (size_t f = 0; f < b.pm.mesh.triangles.size(); f += 3) {
    double a = unit(rng), c = unit(rng);
    if (a + c > 1.0)
      a = 1.0 - a, c = 1.0 - c;
    const glm::ivec3& t = b.pm.mesh.triangles[f];
    const glm::dvec3 p = (1 - a - c) * b.pm.mesh.positions[t[0]] + a * b.pm.mesh.positions[t[1]] +
                         c * b.pm.mesh.positions[t[2]];
    const glm::vec2 uv = float(1 - a - c) * b.pm.corner_uv[3 * f] +
                         float(a) * b.pm.corner_uv[3 * f + 1] +
                         float(c) * b.pm.corner_uv[3 * f + 2];
    distance.push_back(glm::length(glm::dvec3(sample_position(b.image, uv)) - p) / diagonal *
                       100.0);
  }
  std::sort(distance.begin(), distance.end());
  return distance[distance.size() * 95 / 100];
}

struct Expectation {
  const char* mesh;
  const char* route_start;  ///< the first chart's route
};

void PrintTo(const Expectation& e, std::ostream* os) {
  *os << e.mesh;
}

class SharedMesh : public ::testing::TestWithParam<Expectation> {};

TEST_P(SharedMesh, RouteFlipsCoverageAndReconstructionAt256) {
  const Expectation e = GetParam();
  Built b;
  ASSERT_NO_FATAL_FAILURE(build(e.mesh, 256, b));
  const GeometryImageReport& r = b.report;
  ASSERT_FALSE(r.charts.empty());
  EXPECT_EQ(r.charts[0].route, e.route_start) << r.route;
  EXPECT_EQ(r.flipped, 0u);
  EXPECT_GT(r.coverage, 0.5);
  EXPECT_EQ(r.dropped_components, 0u);
  // Nothing dropped: every input face (less degenerate and duplicate ones) is in a chart.
  size_t faces = 0;
  for (const ChartReport& c : r.charts)
    faces += c.faces;
  EXPECT_EQ(faces, b.pm.mesh.triangles.size());
  EXPECT_GE(faces + r.repair.degenerate_faces + r.repair.duplicate_faces, b.input.triangles.size());
  EXPECT_EQ(r.degenerate, 0u);
  // Reconstruction error in % of the diagonal (measured at 256^2, 20K samples: mesh -> image
  // means 0.013-0.044, p99 0.25-0.62; image -> mesh means 0.006-0.019, p99 0.06-0.21).
  EXPECT_LT(r.mesh_to_image.mean, 0.08) << e.mesh;
  EXPECT_LT(r.mesh_to_image.p99, 1.2) << e.mesh;
  EXPECT_LT(r.image_to_mesh.mean, 0.04) << e.mesh;
  EXPECT_LT(r.image_to_mesh.p99, 0.5) << e.mesh;
  EXPECT_EQ(r.mesh_to_image.samples, 20000u);
  // The uv of every corner finds its face in the image.
  EXPECT_LT(uv_contract_p95(b), 0.5) << e.mesh;  // measured 0.09 (spot) to 0.29 (suzanne)
}

INSTANTIATE_TEST_SUITE_P(GeometryImage, SharedMesh,
                         ::testing::Values(Expectation{"spot.obj", "orbifold"},
                                           Expectation{"cow.obj", "orbifold"},
                                           Expectation{"homer.obj", "orbifold"},
                                           Expectation{"rocker-arm.obj", "cut-graph+disk"},
                                           Expectation{"teapot.obj", "disk"},
                                           Expectation{"suzanne.obj", "disk"}),
                         [](const auto& info) {
                           std::string name = info.param.mesh;
                           name = name.substr(0, name.find('.'));
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(GeometryImage, SeveralComponentsAreAllCharted) {
  for (const char* mesh : {"teapot.obj", "suzanne.obj"}) {
    Built b;
    ASSERT_NO_FATAL_FAILURE(build(mesh, 128, b, false));
    const TopologyReport input = analyze_topology(b.input);
    EXPECT_GT(input.components.size(), 1u) << mesh;
    EXPECT_GT(b.report.components, 1u) << mesh;  // after welding and repair
    EXPECT_GE(b.report.charts.size(), b.report.components) << mesh;
    for (const ChartReport& c : b.report.charts) {
      EXPECT_GE(c.rect.size, kMinChartTexels);
      EXPECT_LE(c.rect.x + c.rect.size, 128);
      EXPECT_LE(c.rect.y + c.rect.size, 128);
    }
  }
}

TEST(GeometryImage, LargestComponentSaysWhatItDropped) {
  TriangleMesh teapot;
  std::string error;
  ASSERT_TRUE(
      load_mesh(std::string(gfield::build_paths::mesh_dir()) + "/teapot.obj", teapot, error));
  GeometryImageOptions options;
  options.size = 64;
  options.measure = false;
  options.components = ComponentSelection::kLargest;
  GeometryImage image;
  ParameterizedMesh pm;
  GeometryImageReport report;
  ASSERT_TRUE(build_geometry_image(teapot, options, image, pm, report, error)) << error;
  EXPECT_EQ(report.dropped_components, report.components - 1);
  EXPECT_GT(report.dropped_faces, 0u);
  EXPECT_EQ(pm.mesh.triangles.size() + report.dropped_faces,
            teapot.triangles.size() + report.repair.filled_faces);
  EXPECT_NE(geometry_image_report_to_text(report).find("dropped:"), std::string::npos);
}

TEST(GeometryImage, OrbifoldTilingFillsTheSquareWithoutSeams) {
  Built b;
  ASSERT_NO_FATAL_FAILURE(build("spot.obj", 128, b, false, /*split=*/false));
  ASSERT_EQ(b.report.route, "orbifold");
  EXPECT_EQ(b.report.coverage, 1.0);
  // No seam inside the square: neighbouring texels are close on the surface (a seam would join
  // points a large part of the model apart).
  const double diagonal = diagonal_of(b.pm.mesh.positions);
  double jump = 0.0;
  for (int j = 0; j < 128; ++j)
    for (int i = 0; i + 1 < 128; ++i) {
      jump = std::max(jump, double(glm::length(b.image.position[texel_index(b.image, i, j)] -
                                               b.image.position[texel_index(b.image, i + 1, j)])));
      jump = std::max(jump, double(glm::length(b.image.position[texel_index(b.image, j, i)] -
                                               b.image.position[texel_index(b.image, j, i + 1)])));
    }
  EXPECT_LT(jump / diagonal, 0.08);
  // Unit normals, continuous across the seam as well.
  for (const glm::vec3& n : b.image.normal)
    ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
}

TEST(GeometryImage, BoxIsThePaddedBoundsOfTheRepairedMesh) {
  Built b;
  ASSERT_NO_FATAL_FAILURE(build("suzanne.obj", 64, b, false));
  std::vector<glm::vec3> points(b.pm.mesh.positions.begin(), b.pm.mesh.positions.end());
  const Box box = padded_bounds(points.data(), points.size(), kBoxPadding);
  EXPECT_EQ(b.image.box.min, box.min);
  EXPECT_EQ(b.image.box.max, box.max);
  for (const glm::vec3& p : b.image.position) {
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, box.min)) &&
                glm::all(glm::lessThanEqual(p, box.max)));
  }
}

// The ray offset: the image surface lies within it of about 98% of the mesh's surface (checked
// at points of another seed), a coarser image needs more, and an unmeasured image keeps the least.
TEST(GeometryImage, RayOffsetCoversTheImagesDeviationFromTheMesh) {
  float offsets[2];
  const int sizes[2] = {32, 128};
  for (int i = 0; i < 2; ++i) {
    Built b;
    ASSERT_NO_FATAL_FAILURE(build("suzanne.obj", sizes[i], b));
    offsets[i] = b.image.ray_offset;
    const double offset = double(b.image.ray_offset) * double(diagonal(b.image.box));
    const std::vector<double> d =
        distances_to_surface(sample_surface(b.input, 20000, 99), geometry_image_surface(b.image));
    const double farther =
        double(std::count_if(d.begin(), d.end(), [&](double x) { return x > offset; })) /
        double(d.size());
    std::printf("size %d: ray offset %.3g, %.2f%% of the surface farther\n", sizes[i],
                double(offsets[i]), 100.0 * farther);
    EXPECT_GT(farther, 0.005);
    EXPECT_LT(farther, 0.04);
  }
  EXPECT_GT(offsets[0], 2.0f * offsets[1]);
  Built unmeasured;
  ASSERT_NO_FATAL_FAILURE(build("suzanne.obj", 32, unmeasured, false));
  EXPECT_EQ(unmeasured.image.ray_offset, kMinRayOffset);
}

// --size auto: 512^2, doubled while the mean mesh -> image distance exceeds the target (spot:
// about 0.0036% of the diagonal at 512^2, 0.0010% at 1024^2), never beyond the largest size.
TEST(GeometryImage, AutomaticSizeDoublesUntilTheMeanErrorIsReached) {
  TriangleMesh input;
  std::string error;
  ASSERT_TRUE(load_mesh(std::string(gfield::build_paths::mesh_dir()) + "/spot.obj", input, error))
      << error;
  const double targets[3] = {kDefaultMaxMeanError, 0.002, 1e-6};
  const int expected[3] = {512, 1024, 1024};
  float offsets[3];
  for (int t = 0; t < 3; ++t) {
    GeometryImageOptions options;
    options.max_mean_error = targets[t];
    options.measure = false;  // an automatic size measures the mesh -> image distance anyway
    options.error_samples = 20000;
    GeometryImage image;
    ParameterizedMesh pm;
    GeometryImageReport report;
    ASSERT_TRUE(build_geometry_image(input, options, image, pm, report, error)) << error;
    const std::vector<SizeTrial>& trials = report.size_trials;
    ASSERT_FALSE(trials.empty());
    EXPECT_EQ(image.size, expected[t]) << "target " << targets[t];
    EXPECT_EQ(image.size, trials.back().size);
    EXPECT_EQ(report.max_mean_error, targets[t]);
    for (size_t k = 0; k < trials.size(); ++k) {
      std::printf("target %.4g%%: %d^2 mean %.4f%%\n", targets[t], trials[k].size,
                  trials[k].mesh_to_image_mean);
      EXPECT_EQ(trials[k].size, kAutoImageSizes[k]);
      if (k + 1 < trials.size()) {
        EXPECT_GT(trials[k].mesh_to_image_mean, targets[t]);
      } else if (trials[k].mesh_to_image_mean > targets[t]) {
        EXPECT_EQ(trials[k].size, kAutoImageSizes[std::size(kAutoImageSizes) - 1]);
      }
    }
    if (trials.size() == 2) {
      EXPECT_LT(trials[1].mesh_to_image_mean, 0.5 * trials[0].mesh_to_image_mean);
    }
    EXPECT_EQ(pm.mesh.triangles.size() * 3, pm.corner_uv.size());
    offsets[t] = image.ray_offset;
  }
  EXPECT_GT(offsets[0], 1.5f * offsets[1]);  // the finer image deviates less from the mesh
  EXPECT_EQ(offsets[1], offsets[2]);
}

TEST(GeometryImage, DeterministicOutput) {
  Built a, b;
  ASSERT_NO_FATAL_FAILURE(build("spot.obj", 64, a, false));
  ASSERT_NO_FATAL_FAILURE(build("spot.obj", 64, b, false));
  EXPECT_EQ(a.image.position, b.image.position);
  EXPECT_EQ(a.image.normal, b.image.normal);
  EXPECT_EQ(a.pm.corner_uv, b.pm.corner_uv);
}

TEST(GeometryImage, BadInputGetsAnErrorOrAValidFallback) {
  GeometryImageOptions options;
  options.size = 32;
  options.measure = false;
  GeometryImage image;
  ParameterizedMesh pm;
  GeometryImageReport report;
  std::string error;

  TriangleMesh triangle{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}};
  ASSERT_TRUE(build_geometry_image(triangle, options, image, pm, report, error)) << error;
  EXPECT_EQ(report.flipped, 0u);
  EXPECT_EQ(report.charts[0].route, "triangle");
  EXPECT_GT(report.coverage, 0.3);

  TriangleMesh collinear{{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}, {{0, 1, 2}}};
  EXPECT_FALSE(build_geometry_image(collinear, options, image, pm, report, error));
  EXPECT_NE(error.find("zero area"), std::string::npos) << error;

  TriangleMesh collapsed{{{1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}}, {{0, 1, 2}, {1, 2, 3}}};
  EXPECT_FALSE(build_geometry_image(collapsed, options, image, pm, report, error));

  TriangleMesh huge{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {}};
  huge.triangles.assign(kMaxFaces + 1, glm::ivec3(0, 1, 2));
  EXPECT_FALSE(build_geometry_image(huge, options, image, pm, report, error));
  EXPECT_NE(error.find("at most"), std::string::npos) << error;
  huge = {};

  // Three triangles on one edge (non-manifold) and a Moebius strip (not orientable): repair
  // splits them; whatever comes out has no flipped face.
  TriangleMesh fin{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}},
                   {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}};
  if (build_geometry_image(fin, options, image, pm, report, error)) {
    EXPECT_EQ(report.flipped, 0u);
  }
  TriangleMesh moebius;
  const int n = 12;
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * M_PI * k / n;
    for (int s : {-1, 1}) {
      const double w = 0.3 * s, t = a / 2.0;
      moebius.positions.push_back({(1 + w * std::cos(t)) * std::cos(a),
                                   (1 + w * std::cos(t)) * std::sin(a), w * std::sin(t)});
    }
  }
  for (int k = 0; k < n; ++k) {
    int a0 = 2 * k, a1 = 2 * k + 1, b0 = 2 * ((k + 1) % n), b1 = b0 + 1;
    if (k == n - 1)
      std::swap(b0, b1);  // the half twist
    moebius.triangles.push_back({a0, b0, a1});
    moebius.triangles.push_back({a1, b0, b1});
  }
  if (build_geometry_image(moebius, options, image, pm, report, error)) {
    EXPECT_EQ(report.flipped, 0u);
  }

  options.size = 4;
  EXPECT_FALSE(build_geometry_image(triangle, options, image, pm, report, error));
}

/// A torus of revolution, `n` x `m` quads split in two.
TriangleMesh torus(int n, int m) {
  TriangleMesh mesh;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double a = 2 * M_PI * i / n, b = 2 * M_PI * j / m;
      mesh.positions.push_back(
          {(2 + std::cos(b)) * std::cos(a), (2 + std::cos(b)) * std::sin(a), std::sin(b)});
    }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const int a = i * m + j, b = ((i + 1) % n) * m + j, c = ((i + 1) % n) * m + (j + 1) % m,
                d = i * m + (j + 1) % m;
      mesh.triangles.push_back({a, b, c});
      mesh.triangles.push_back({a, c, d});
    }
  return mesh;
}

TEST(CutGraph, TreeCotreeCutsATorusIntoADisk) {
  const TriangleMesh mesh = torus(24, 12);
  const std::vector<Edge> cut = tree_cotree_cut(mesh);
  EXPECT_FALSE(cut.empty());
  const DiskMesh disk = cut_open(mesh, cut);
  // Euler characteristic of the cut surface: V' - E' + F = 1 for a disk.
  std::set<std::pair<int, int>> edges;
  for (const glm::ivec3& t : disk.triangles)
    for (int k = 0; k < 3; ++k)
      edges.insert({std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])});
  EXPECT_EQ(long(disk.vertex_origin.size()) - long(edges.size()) + long(disk.triangles.size()), 1);
  // A genus-0 closed mesh needs no cut.
  TriangleMesh spot;
  std::string error;
  ASSERT_TRUE(load_mesh(std::string(gfield::build_paths::mesh_dir()) + "/spot.obj", spot, error));
  EXPECT_TRUE(tree_cotree_cut(spot).empty());
}

TEST(CutGraph, TorusImageHasNoFlips) {
  GeometryImageOptions options;
  options.size = 64;
  options.error_samples = 5000;
  GeometryImage image;
  ParameterizedMesh pm;
  GeometryImageReport report;
  std::string error;
  ASSERT_TRUE(build_geometry_image(torus(48, 24), options, image, pm, report, error)) << error;
  EXPECT_EQ(report.charts[0].route, "cut-graph+disk");
  EXPECT_EQ(report.charts[0].genus, 1);
  EXPECT_EQ(report.flipped, 0u);
  EXPECT_LT(report.mesh_to_image.p99, 3.0);  // 64^2
}

TEST(ChartPacking, RectsAreDisjointWithGuttersAndInside) {
  std::vector<double> areas{5.0, 1.0, 1.0, 0.3, 0.01, 2.5, 0.7};
  std::vector<ChartRect> rects;
  std::string error;
  ASSERT_TRUE(pack_charts(areas, 256, 2, rects, error)) << error;
  for (size_t a = 0; a < rects.size(); ++a) {
    EXPECT_GE(rects[a].x, 0);
    EXPECT_LE(rects[a].x + rects[a].size, 256);
    EXPECT_LE(rects[a].y + rects[a].size, 256);
    for (size_t b = a + 1; b < rects.size(); ++b) {
      const bool apart = rects[a].x + rects[a].size + 2 <= rects[b].x ||
                         rects[b].x + rects[b].size + 2 <= rects[a].x ||
                         rects[a].y + rects[a].size + 2 <= rects[b].y ||
                         rects[b].y + rects[b].size + 2 <= rects[a].y;
      EXPECT_TRUE(apart) << a << " " << b;
    }
  }
  EXPECT_GT(rects[0].size, rects[1].size);  // area-proportional
  std::vector<double> many(10000, 1.0);
  EXPECT_FALSE(pack_charts(many, 64, 2, rects, error));
}

TEST(SurfaceDistance, MatchesTheAnalyticDistanceToAPlane) {
  const TriangleMesh square{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}}};
  const std::vector<glm::dvec3> points{{0.5, 0.5, 0.25}, {0.2, 0.7, -0.5}, {2.0, 0.5, 0.0}};
  const std::vector<double> d = distances_to_surface(points, square);
  EXPECT_NEAR(d[0], 0.25, 1e-12);
  EXPECT_NEAR(d[1], 0.5, 1e-12);
  EXPECT_NEAR(d[2], 1.0, 1e-12);
  const std::vector<glm::dvec3> samples = sample_surface(square, 1000, 3);
  ASSERT_EQ(samples.size(), 1000u);
  for (const glm::dvec3& p : samples)
    ASSERT_EQ(p.z, 0.0);
}

TEST(ParameterizedMeshFile, RoundTrip) {
  ParameterizedMesh pm;
  pm.mesh = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0.5}}, {{0, 1, 2}, {1, 3, 2}}};
  pm.corner_uv = {{0.1f, 0.1f}, {0.9f, 0.1f}, {0.1f, 0.9f},
                  {0.9f, 0.1f}, {0.9f, 0.9f}, {0.1f, 0.9f}};
  const std::string path = std::string(gfield::build_paths::test_tmp()) + "/roundtrip.gimage.obj";
  std::string error;
  ASSERT_TRUE(save_parameterized_mesh(path, pm, error)) << error;
  ParameterizedMesh back;
  ASSERT_TRUE(load_parameterized_mesh(path, back, error)) << error;
  EXPECT_EQ(back.mesh.positions, pm.mesh.positions);
  EXPECT_EQ(back.mesh.triangles, pm.mesh.triangles);
  EXPECT_EQ(back.corner_uv, pm.corner_uv);
  EXPECT_EQ(parameterized_mesh_path("a/b.gimage.exr"), "a/b.gimage.obj");
}

TEST(CliImage, WritesTheImageAndTheUvMeshOrNothing) {
  namespace fs = std::filesystem;
  const std::string tmp = gfield::build_paths::test_tmp();
  const std::string out = tmp + "/suzanne.gimage.exr", json = tmp + "/suzanne.gimage.json";
  fs::remove(out);
  fs::remove(tmp + "/suzanne.gimage.obj");
  const test::CliRun run = test::run_cli("image " + std::string(gfield::build_paths::mesh_dir()) +
                                         "/suzanne.obj -o " + out + " --size 64 --json " + json);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("route: "), std::string::npos) << run.out;
  GeometryImage image;
  std::string error;
  ASSERT_TRUE(load_geometry_image(out, image, error)) << error;
  EXPECT_EQ(image.size, 64);
  EXPECT_EQ(image.source, "suzanne.obj");
  ParameterizedMesh pm;
  ASSERT_TRUE(load_parameterized_mesh(tmp + "/suzanne.gimage.obj", pm, error)) << error;
  EXPECT_GT(pm.mesh.triangles.size(), 900u);
  std::ifstream in(json);
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["flipped_faces"], 0);
  EXPECT_GE(j["reconstruction_error"]["mesh_to_image"]["samples"], 100000);

  // Bad input: exit code 2, one line, no output.
  const std::string bad = tmp + "/bad.gimage.exr";
  fs::remove(bad);
  for (const std::string& args :
       {"image " + tmp + "/missing.obj -o " + bad,
        "image " + std::string(gfield::build_paths::mesh_dir()) +
            "/teapot.obj --method orbifold -o " + bad,
        "image " + std::string(gfield::build_paths::mesh_dir()) + "/teapot.obj --size 12a -o " +
            bad,
        "image " + std::string(gfield::build_paths::mesh_dir()) + "/teapot.obj --size 4 -o " + bad,
        "image " + std::string(gfield::build_paths::mesh_dir()) +
            "/teapot.obj --max-image-error 0 -o " + bad}) {
    const test::CliRun failed = test::run_cli(args);
    EXPECT_EQ(failed.exit_code, 2) << args;
    EXPECT_EQ(std::count(failed.err.begin(), failed.err.end(), '\n'), 1) << failed.err;
    EXPECT_FALSE(fs::exists(bad));
    EXPECT_FALSE(fs::exists(tmp + "/bad.gimage.obj"));
  }
}

}  // namespace
}  // namespace gfield
