#include "preprocess/verify.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <random>

#include "geometry/outward_normals.hpp"
#include "geometry/parameterized_mesh.hpp"
#include "gfield/asset_source.hpp"
#include "gfield/build_id.hpp"
#include "gfield/exr_io.hpp"
#include "gfield/file_read.hpp"
#include "gfield/gpu_storage.hpp"
#include "gfield/printable.hpp"
#include "gfield/stopwatch.hpp"
#include "preprocess/asset_report.hpp"
#include "preprocess/portable_random.hpp"

namespace gfield {
namespace {

/// One ray's answer reduced to what is compared.
struct Answer {
  bool hit = false;
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f};
};

constexpr LookupMode kModes[] = {LookupMode::kNearest, LookupMode::kLinear, LookupMode::kRefined};

double percentile(std::vector<float>& values, double p) {
  if (values.empty()) {
    return 0.0;
  }
  const size_t k = size_t(p * double(values.size() - 1) + 0.5);
  std::nth_element(values.begin(), values.begin() + ptrdiff_t(k), values.end());
  return double(values[k]);
}

/// A reference mesh: Embree scene plus the smooth normal field the geometry image samples (unit
/// vertex normals, interpolated with the hit's barycentrics).
struct Exact {
  const EmbreeMesh& embree;
  const TriangleMesh& mesh;
  std::vector<glm::dvec3> normals;

  Exact(const EmbreeMesh& e, const TriangleMesh& m)
      : embree(e), mesh(m), normals(angle_weighted_vertex_normals(m)) {}
};

/// The exact first (or last) hit of `ray` in [t_min, t_max], cast with rtcIntersect1. `ignored`
/// >= 0: a ray leaving that triangle, cast past the triangle itself.
Answer exact_answer(const Exact& reference, const Box& box, const Ray& ray, bool last,
                    int ignored = -1) {
  const EmbreeMesh& exact = reference.embree;
  Answer a;
  RayHit h;
  if (ignored >= 0) {
    h = intersect(exact, ray.origin, ray.direction, ray.t_min, ray.t_max, ignored);
    if (h.hit) {
      a.position = ray.origin + h.t * ray.direction;
    }
  } else if (!last) {
    h = intersect(exact, ray.origin, ray.direction, ray.t_min, ray.t_max);
    if (h.hit) {
      a.position = ray.origin + h.t * ray.direction;
    }
  } else {
    // Cast the reversed line from the far end of the range (clipped to the box) backwards.
    const CubeCrossing c = clip_to_unit_cube(to_unit_cube(box, ray.origin),
                                             direction_to_unit_cube(box, ray.direction));
    if (!c.hit) {
      return a;
    }
    const float t_far = std::min(ray.t_max, c.t_exit);
    if (t_far < ray.t_min) {
      return a;
    }
    const glm::vec3 far = ray.origin + t_far * ray.direction;
    h = intersect(exact, far, -ray.direction, 0.0f, t_far - ray.t_min);
    if (h.hit) {
      a.position = far - h.t * ray.direction;
    }
  }
  a.hit = h.hit;
  if (h.hit) {
    const glm::ivec3 t = reference.mesh.triangles[size_t(h.triangle)];
    const glm::dvec3 n = (1.0 - h.u - h.v) * reference.normals[size_t(t[0])] +
                         double(h.u) * reference.normals[size_t(t[1])] +
                         double(h.v) * reference.normals[size_t(t[2])];
    a.normal =
        glm::length(n) > 0.0 ? glm::vec3(glm::normalize(n)) : glm::normalize(h.geometric_normal);
  }
  return a;
}

/// `ignored`: empty, or the triangle each ray leaves (surface rays).
std::vector<Answer> exact_answers(const Exact& exact, const Box& box, const std::vector<Ray>& rays,
                                  bool last, const std::vector<int>& ignored = {}) {
  std::vector<Answer> answers(rays.size());
  tbb::parallel_for(size_t(0), rays.size(), [&](size_t i) {
    answers[i] = exact_answer(exact, box, rays[i], last, ignored.empty() ? -1 : ignored[i]);
  });
  return answers;
}

/// `leaving`: null, or how `rays` leave the surface (SurfaceRays::self_origins, self_t_min,
/// facing and any_hit), looked up as lookup_first_hit_leaving.
std::vector<Answer> lookup_answers(const FieldLookup& lookup, const std::vector<Ray>& rays,
                                   LookupMode mode, bool last, double& seconds,
                                   const SurfaceRays* leaving = nullptr) {
  std::vector<Answer> answers(rays.size());
  Stopwatch watch;
  tbb::parallel_for(size_t(0), rays.size(), [&](size_t i) {
    const FieldHit h = leaving != nullptr
                           ? lookup_first_hit_leaving(lookup, rays[i], leaving->self_origins[i],
                                                      leaving->self_t_min, leaving->facing[i], mode,
                                                      leaving->any_hit)
                       : last ? lookup_last_hit(lookup, rays[i], mode)
                              : lookup_first_hit(lookup, rays[i], mode);
    answers[i] = {h.hit, h.position, h.normal};
  });
  seconds = watch.seconds();
  return answers;
}

AccuracyStats compare(const std::vector<Answer>& answers, const std::vector<Answer>& exact,
                      float diagonal_length) {
  AccuracyStats s;
  s.rays = answers.size();
  std::vector<float> position_errors;
  std::vector<float> normal_errors;
  for (size_t i = 0; i < answers.size(); ++i) {
    s.agree += size_t(answers[i].hit == exact[i].hit);
    s.exact_hits += size_t(exact[i].hit);
    s.answer_hits += size_t(answers[i].hit);
    if (answers[i].hit && exact[i].hit) {
      position_errors.push_back(100.0f * glm::distance(answers[i].position, exact[i].position) /
                                diagonal_length);
      const float c = glm::clamp(glm::dot(answers[i].normal, exact[i].normal), -1.0f, 1.0f);
      normal_errors.push_back(glm::degrees(std::acos(c)));
    }
  }
  s.both_hit = position_errors.size();
  s.position_median = percentile(position_errors, 0.5);
  s.position_p95 = percentile(position_errors, 0.95);
  s.position_p99 = percentile(position_errors, 0.99);
  s.normal_median = percentile(normal_errors, 0.5);
  s.normal_p95 = percentile(normal_errors, 0.95);
  return s;
}

/// Lookups and exact casts of one ray family against the reference meshes.
struct Family {
  std::string name;
  std::vector<Ray> rays;
  bool with_last = false;      ///< also the last hit (segments only)
  std::vector<int> ignored;    ///< the triangle each ray leaves (surface rays), else empty
  std::vector<int> layers{0};  ///< layers looked up per run (0: all K)
  /// "": against every reference mesh; else only against the one of this label (rays leaving
  /// the surface: the mesh they leave)
  std::string reference;
  /// surface rays: how they leave (self_origins, self_t_min, facing; the rays and triangles are
  /// the family's above), else empty
  SurfaceRays leaving = {};
};

}  // namespace

AccuracyStats verify_table(const GeometryField& field, const GeometryImage& image,
                           const EmbreeMesh& embree, const TriangleMesh& mesh, size_t pairs,
                           uint64_t seed) {
  const Exact exact(embree, mesh);
  const int n = field.samples_per_side;
  std::mt19937_64 rng(seed);
  const UniformInt sample{0, sample_count(n) - 1};
  std::vector<glm::ivec2> chosen(pairs);
  for (glm::ivec2& pair : chosen) {
    do {
      pair = glm::ivec2(sample(rng), sample(rng));
    } while (pair.x / (n * n) == pair.y / (n * n));
  }
  std::vector<Answer> stored(pairs);
  std::vector<Answer> cast(pairs);
  Stopwatch watch;
  tbb::parallel_for(size_t(0), pairs, [&](size_t i) {
    const glm::vec2 uv = field_uv(field, chosen[i].x, chosen[i].y);
    if (is_field_hit(uv)) {
      stored[i] = {true, sample_position(image, uv), sample_normal(image, uv)};
    }
  });
  const double seconds = watch.seconds();
  tbb::parallel_for(size_t(0), pairs, [&](size_t i) {
    const glm::vec3 entry = from_unit_cube(field.box, sample_point(face_sample(chosen[i].x, n), n));
    const glm::vec3 exit = from_unit_cube(field.box, sample_point(face_sample(chosen[i].y, n), n));
    cast[i] = exact_answer(exact, field.box, Ray{entry, exit - entry, 0.0f, 1.0f}, false);
  });
  AccuracyStats s = compare(stored, cast, diagonal(field.box));
  s.seconds = seconds;
  return s;
}

AccuracyStats verify_lookup(const FieldLookup& lookup, const EmbreeMesh& embree,
                            const TriangleMesh& mesh, const std::vector<Ray>& rays, LookupMode mode,
                            bool last, const std::vector<int>& ignored) {
  const Exact exact(embree, mesh);
  double seconds = 0.0;
  const std::vector<Answer> answers = lookup_answers(lookup, rays, mode, last, seconds);
  const std::vector<Answer> cast = exact_answers(exact, lookup.field->box, rays, last, ignored);
  AccuracyStats s = compare(answers, cast, diagonal(lookup.field->box));
  s.seconds = seconds;
  return s;
}

AccuracyStats verify_lookup(const FieldLookup& lookup, const EmbreeMesh& embree,
                            const TriangleMesh& mesh, const SurfaceRays& rays, LookupMode mode) {
  const Exact exact(embree, mesh);
  double seconds = 0.0;
  const std::vector<Answer> answers =
      lookup_answers(lookup, rays.rays, mode, false, seconds, &rays);
  const std::vector<Answer> cast =
      exact_answers(exact, lookup.field->box, rays.rays, false, rays.triangles);
  AccuracyStats s = compare(answers, cast, diagonal(lookup.field->box));
  s.seconds = seconds;
  return s;
}

namespace {

/// The original mesh file of asset NAME: the option, the report's source path, or the image's
/// source as a path (as given, or beside the asset). Empty when none exists.
MeshSource find_original(const std::string& name, const std::optional<AssetReport>& report,
                         const VerifyOptions& options, const std::string& source) {
  namespace fs = std::filesystem;
  if (!options.original.empty()) {
    return {options.original, options.original_part, options.original_outside_paths};
  }
  if (report && fs::exists(report->source_path)) {
    return {report->source_path, report->mesh_part, options.original_outside_paths};
  }
  if (!source.empty()) {
    if (fs::exists(source)) {
      return {source, "", options.original_outside_paths};
    }
    const fs::path beside = fs::path(name).parent_path() / fs::path(source).filename();
    if (fs::exists(beside)) {
      return {beside.string(), "", options.original_outside_paths};
    }
  }
  return {};
}

/// The report beside the asset: none where there is none. False with an error when one is
/// there but cannot be read.
bool read_report_beside(const std::string& report_path, std::optional<AssetReport>& report,
                        std::string& error) {
  report.reset();
  return file_problem(report_path) == "no such file" ||
         read_asset_report(report_path, report.emplace(), error);
}

/// The report beside the asset, where there is one, must be of the image's build.
bool check_report(const std::string& report_path, const GeometryImage& image,
                  const std::string& image_path, std::string& error) {
  std::error_code ec;
  if (!std::filesystem::exists(report_path, ec)) {
    return true;
  }
  std::string id;
  return read_report_build_id(report_path, id, error) &&
         check_same_build(report_path, id, image_path, image.build_id, error);
}

/// The field, image and parameterised mesh of `files`, all of one build (and the report where
/// there is one), and the lookup over them with the field as the GPU stores it at `field_bits`.
bool load_asset(const AssetFiles& files, GeometryField& field, GeometryImage& image,
                ParameterizedMesh& pm, int field_bits, FieldLookup& lookup, std::string& error) {
  if (!load_geometry_field(files.field, field, error) ||
      !load_geometry_image(files.image, image, error) ||
      !load_parameterized_mesh_of(image, files.image, pm, error)) {
    return false;
  }
  field = quantized_field(field, field_bits);
  if (!mesh_inside_box(pm, image.box)) {
    error = files.parameterized_mesh + ": the mesh does not lie inside the geometry image's box (" +
            files.image + "): they do not belong together";
    return false;
  }
  if (!make_field_lookup(field, image, lookup, error)) {
    error = files.field + ": does not match " + files.image + " (" + error + ")";
    return false;
  }
  return check_report(files.report, image, files.image, error);
}

struct Reference {
  std::string label;
  std::string path;
  TriangleMesh mesh;
};

/// The lookup answers of one family in one mode (first or last hit) with some layers; `key`
/// names the family in the report (surface families per K: surface_rays_k1, ...).
struct Run {
  std::string family;
  std::string key;
  std::string mode;
  bool last;
  std::vector<Answer> answers;
  double seconds;
};

/// The rays of family `name` (surface_rays, mirror_rays or glass_rays) leaving the surface of
/// `mesh`, held by `embree`.
SurfaceRays leaving_rays(const std::string& name, const EmbreeMesh& embree,
                         const TriangleMesh& mesh, const Box& box, SurfaceOffsets offsets,
                         const VerifyOptions& options) {
  if (name == "surface_rays") {
    return random_surface_rays(mesh, options.rays, offsets, options.seed + 3);
  }
  if (name == "mirror_rays") {
    return mirror_surface_rays(embree, mesh, box, options.rays, offsets, options.seed + 4);
  }
  return glass_surface_rays(embree, mesh, box, options.rays, offsets, options.seed + 5);
}

/// The ray families: box and view rays with all layers; rays leaving the surface of `mesh` (held
/// by `embree`; reference `label`: the built mesh, or the original of an image built through a
/// proxy) (random points and hemisphere directions; mirror reflections and refractions into the
/// solid, index of refraction 1.5, of view rays) with K = 1 and with all K.
std::vector<Family> make_families(const GeometryField& field, const GeometryImage& image,
                                  const EmbreeMesh& embree, const TriangleMesh& mesh,
                                  const std::string& label, const VerifyOptions& options) {
  std::vector<Family> families;
  Family box{"box_rays", random_box_rays(field.box, options.rays, options.seed), true, {}, {0}, {}};
  families.push_back(std::move(box));
  Family view{
      "view_rays", random_view_rays(field.box, options.rays, options.seed + 1), false, {}, {0}, {}};
  families.push_back(std::move(view));
  const SurfaceOffsets offsets = surface_offsets(image, field.box);
  const std::vector<int> layers =
      field.layers > 1 ? std::vector<int>{1, field.layers} : std::vector<int>{1};
  for (const std::string name : {"surface_rays", "mirror_rays", "glass_rays"}) {
    SurfaceRays rays = leaving_rays(name, embree, mesh, field.box, offsets, options);
    Family family{name, std::move(rays.rays), false, std::move(rays.triangles), layers, label};
    family.leaving.self_origins = std::move(rays.self_origins);
    family.leaving.self_t_min = rays.self_t_min;
    family.leaving.facing = std::move(rays.facing);
    families.push_back(std::move(family));
  }
  return families;
}

std::vector<Run> lookup_runs(const FieldLookup& lookup, const std::vector<Family>& families) {
  std::vector<Run> runs;
  for (const Family& family : families) {
    for (int layers : family.layers) {
      FieldLookup limited = lookup;
      limited.layers = layers;
      const std::string key =
          layers > 0 ? family.name + "_k" + std::to_string(layers) : family.name;
      for (LookupMode mode : kModes) {
        for (bool last : {false, true}) {
          if (last && (!family.with_last || mode != LookupMode::kRefined)) {
            continue;
          }
          Run run{family.name, key, lookup_mode_name(mode), last, {}, 0.0};
          run.answers =
              lookup_answers(limited, family.rays, mode, last, run.seconds,
                             family.leaving.self_origins.empty() ? nullptr : &family.leaving);
          runs.push_back(std::move(run));
        }
      }
    }
  }
  return runs;
}

/// The share of a surface family's rays whose exact first hit lies before self_t_min, where the
/// lookup tells a hit from the surface the ray leaves only by its facing (gf_trace_leaving).
double near_hit_share(const Exact& exact, const Box& box, const Family& family) {
  std::vector<Ray> from_origin = family.rays;
  for (Ray& ray : from_origin) {
    ray.t_max = family.leaving.self_t_min;
  }
  const std::vector<Answer> near = exact_answers(exact, box, from_origin, false, family.ignored);
  const size_t count =
      size_t(std::count_if(near.begin(), near.end(), [](const Answer& a) { return a.hit; }));
  return near.empty() ? 0.0 : double(count) / double(near.size());
}

/// The accuracy against one reference mesh: the table and every run against its exact casts.
ReferenceAccuracy reference_accuracy(const Reference& reference, const EmbreeMesh& embree,
                                     const GeometryField& field, const GeometryImage& image,
                                     const std::vector<Family>& families,
                                     const std::vector<Run>& runs, const VerifyOptions& options) {
  ReferenceAccuracy r;
  r.mesh = reference.label;
  r.path = printable(reference.path);
  r.table = verify_table(field, image, embree, reference.mesh, options.rays, options.seed + 2);
  const Exact exact(embree, reference.mesh);
  for (const Family& family : families) {
    if (!family.reference.empty() && reference.label != family.reference) {
      continue;
    }
    const std::vector<Answer> first =
        exact_answers(exact, field.box, family.rays, false, family.ignored);
    if (!family.ignored.empty()) {
      r.near_hits[family.name] = near_hit_share(exact, field.box, family);
    }
    std::vector<Answer> last;
    if (family.with_last) {
      last = exact_answers(exact, field.box, family.rays, true);
    }
    for (const Run& run : runs) {
      if (run.family != family.name) {
        continue;
      }
      AccuracyStats s = compare(run.answers, run.last ? last : first, diagonal(field.box));
      s.seconds = run.seconds;
      r.families[run.key][run.last ? run.mode + "_last" : run.mode] = s;
    }
  }
  return r;
}

/// A field that cannot see its mesh is an error, not 100% agreement: none of the table's exact
/// casts hits the mesh (float casts cannot resolve it), or they do and none of its entries does.
/// (The box bounds the mesh, so 100 random box rays always cross some of its surface.)
bool check_field_sees_mesh(const AccuracyStats& table, const std::string& field_file,
                           std::string& error) {
  const size_t rays = table.rays, exact = table.exact_hits, answers = table.answer_hits;
  if (rays < 100 || (exact > 0 && answers > 0))
    return true;
  const std::string of_rays = std::to_string(rays) + " box rays";
  if (exact == 0)
    error =
        field_file + ": no exact cast of " + of_rays + " hits the mesh: float casts cannot see it";
  else
    error = field_file + ": the field has no hit where exact casts hit the mesh (" +
            std::to_string(exact) + " of " + of_rays + ")";
  return false;
}

}  // namespace

bool verify_asset(const std::string& name, const VerifyOptions& options, VerifyReport& report,
                  std::string& error) {
  // An asset republished while its files were read can give files of two builds, or a folder
  // removed under the reader: then the read is taken again, of the build published now.
  for (int attempt = 0;; ++attempt) {
    const std::string before = published_build(name);
    if (verify_asset_files(asset_files(name), name, options, report, error))
      return true;
    if (attempt == 2 || before.empty() || published_build(name) == before)
      return false;
  }
}

bool verify_asset_files(const AssetFiles& read, const std::string& name,
                        const VerifyOptions& options, VerifyReport& report, std::string& error) {
  const AssetFiles shown = asset_files(name);
  GeometryField field;
  GeometryImage image;
  ParameterizedMesh pm;
  if (!valid_field_bits(options.field_bits)) {
    error = shown.field + ": field bits " + std::to_string(options.field_bits) + " not 8, 16 or 32";
    return false;
  }
  FieldLookup lookup;
  if (!load_asset(read, field, image, pm, options.field_bits, lookup, error)) {
    return false;
  }
  std::vector<Reference> references;
  references.push_back({"built", shown.parameterized_mesh, pm.mesh});
  std::optional<AssetReport> asset_report;
  if (!read_report_beside(read.report, asset_report, error)) {
    return false;
  }
  const MeshSource original = find_original(name, asset_report, options, image.source);
  bool checked = false;
  if (!original.file.empty() && !check_asset_source(read.report, original.file, checked, error)) {
    return false;
  }
  if (!original.file.empty()) {
    Reference r{"original", original.file, {}};
    std::vector<std::string> ignored;
    if (!load_mesh(original, r.mesh, nullptr, ignored, error)) {
      return false;
    }
    references.push_back(std::move(r));
  }
  EmbreeMesh built, original_embree;
  if (!built.build(pm.mesh, error)) {
    error = shown.parameterized_mesh + ": " + error;
    return false;
  }
  if (references.size() > 1 && !original_embree.build(references[1].mesh, error)) {
    error = references[1].path + ": " + error;
    return false;
  }
  // An image built through a proxy describes the original: its rays leave the original's surface.
  const bool proxy = options.proxy || (asset_report && asset_report->geometry_image.proxy.used);
  const bool from_original = proxy && references.size() > 1;
  const std::vector<Family> families = make_families(
      field, image, from_original ? original_embree : built,
      from_original ? references[1].mesh : pm.mesh, from_original ? "original" : "built", options);
  const std::vector<Run> runs = lookup_runs(lookup, families);

  report = VerifyReport{};
  report.name = printable(name);
  report.field = printable(shown.field);
  report.samples_per_side = field.samples_per_side;
  report.layers = field.layers;
  report.field_bits = options.field_bits;
  report.image_size = image.size;
  report.ray_offset = image.ray_offset;
  report.source = printable(image.source);
  report.rays_per_family = options.rays;
  report.seed = options.seed;
  report.proxy = proxy;
  for (const Reference& reference : references) {
    report.references.push_back(
        reference_accuracy(reference, reference.label == "built" ? built : original_embree, field,
                           image, families, runs, options));
  }
  if (original.file.empty()) {
    report.original_note = "original mesh file not found (use --original)";
  }
  return check_field_sees_mesh(report.references[0].table, shown.field, error);
}

}  // namespace gfield
