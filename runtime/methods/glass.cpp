#include "runtime/methods/glass.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gfield/glass_displacement.hpp"
#include "geometry/analytic_primitives.hpp"
#include "geometry/mesh_io.hpp"
#include "geometry/outward_normals.hpp"
#include "runtime/gpu_scene.hpp"
#include "runtime/supersample.hpp"

namespace gfield {
namespace {

constexpr float kPi = 3.14159265358979f;
constexpr int kMaxLights = 4;

/// Interleaved vertex: position (object space), normal, uv.
struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 uv;
};

struct TriangleSoup {
  std::vector<Vertex> vertices;
  std::vector<unsigned> indices;
};

/// std430 mirror of GlassOpaque in shaders/glass_composite.frag.
struct GpuOpaque {
  glm::mat4 to_object;
  glm::mat4 to_world;
  glm::vec4 shape;
  glm::vec4 size;
  glm::vec4 color;
  glm::vec4 checker0;
  glm::vec4 checker1;
  glm::ivec4 kind;
};
static_assert(sizeof(GpuOpaque) == 224);

double elapsed_ms(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

int segments(float length, float max_edge) {
  return std::clamp(int(std::ceil(length / max_edge)), 1, 2048);
}

/// A (nu + 1) x (nv + 1) grid of f(u, v) for u, v in [0, 1].
template <class F>
void add_grid(TriangleSoup& soup, int nu, int nv, F f) {
  const unsigned base = unsigned(soup.vertices.size());
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i)
      soup.vertices.push_back(f(float(i) / float(nu), float(j) / float(nv)));
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const unsigned a = base + unsigned(j * (nu + 1) + i);
      const unsigned b = a + 1, c = a + unsigned(nu + 1), d = c + 1;
      soup.indices.insert(soup.indices.end(), {a, b, d, a, d, c});
    }
  }
}

/// The faces of a box of half extents h, texture coordinates as the reference tracer's.
void add_box(TriangleSoup& soup, glm::vec3 h, float max_edge) {
  for (int axis = 0; axis < 3; ++axis) {
    const int a1 = axis == 0 ? 2 : 0;  // X faces: (z, y); Y faces: (x, z); Z faces: (x, y)
    const int a2 = axis == 1 ? 2 : 1;
    for (const float side : {-1.0f, 1.0f}) {
      add_grid(soup, segments(2.0f * h[a1], max_edge), segments(2.0f * h[a2], max_edge),
               [&](float u, float v) {
                 glm::vec3 p(0.0f), n(0.0f);
                 p[axis] = side * h[axis];
                 p[a1] = (u - 0.5f) * 2.0f * h[a1];
                 p[a2] = (v - 0.5f) * 2.0f * h[a2];
                 n[axis] = side;
                 return Vertex{p, n, {u, v}};
               });
    }
  }
}

/// Triangles of an analytic opaque shape in object space (uv as analytic_primitives.cpp).
bool tessellate(const Shape& shape, float max_edge, TriangleSoup& soup) {
  switch (shape.type) {
    case ShapeType::kQuad:
      add_grid(soup, segments(shape.size.x, max_edge), segments(shape.size.y, max_edge),
               [&](float u, float v) {
                 return Vertex{{(u - 0.5f) * shape.size.x, (v - 0.5f) * shape.size.y, 0.0f},
                               {0.0f, 0.0f, 1.0f},
                               {u, v}};
               });
      return true;
    case ShapeType::kBox:
      add_box(soup, 0.5f * shape.size, max_edge);
      return true;
    case ShapeType::kSlab:
      add_box(soup, 0.5f * glm::vec3(shape.size.x, shape.size.y, shape.thickness), max_edge);
      return true;
    case ShapeType::kSphere: {
      const float r = shape.radius;
      add_grid(soup, segments(2.0f * kPi * r, max_edge), segments(kPi * r, max_edge),
               [&](float u, float v) {
                 const float a = 2.0f * kPi * (u - 0.5f), e = kPi * (v - 0.5f);
                 const glm::vec3 n(std::cos(e) * std::sin(a), std::sin(e),
                                   std::cos(e) * std::cos(a));
                 return Vertex{r * n, n, {u, v}};
               });
      return true;
    }
    case ShapeType::kCylinder: {
      const float r = shape.radius, h = shape.height;
      add_grid(soup, segments(2.0f * kPi * r, max_edge), segments(h, max_edge),
               [&](float u, float v) {
                 const float a = 2.0f * kPi * (u - 0.5f);
                 const glm::vec3 n(std::sin(a), 0.0f, std::cos(a));
                 return Vertex{{r * n.x, (v - 0.5f) * h, r * n.z}, n, {u, v}};
               });
      for (const float side : {-1.0f, 1.0f}) {
        add_grid(soup, segments(2.0f * kPi * r, max_edge), segments(r, max_edge),
                 [&](float u, float v) {
                   const float a = 2.0f * kPi * (u - 0.5f);
                   const glm::vec3 p(v * r * std::sin(a), side * 0.5f * h, v * r * std::cos(a));
                   return Vertex{
                       p, {0.0f, side, 0.0f}, {p.x / (2.0f * r) + 0.5f, p.z / (2.0f * r) + 0.5f}};
                 });
      }
      return true;
    }
    case ShapeType::kMesh:
    case ShapeType::kHollowCylinder:
      break;
  }
  return false;
}

/// A mesh file's triangles with the reference tracer's vertex normals (angle-weighted, turned
/// outwards by the signed volume).
bool mesh_soup(const std::string& file, TriangleSoup& soup, std::string& error) {
  TriangleMesh mesh;
  if (!load_mesh(file, mesh, error))
    return false;
  const std::vector<glm::dvec3> normals = outward_vertex_normals(mesh);
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    soup.vertices.push_back({glm::vec3(mesh.positions[v]), glm::vec3(normals[v]), glm::vec2(0.0f)});
  }
  for (const glm::ivec3& f : mesh.triangles)
    soup.indices.insert(soup.indices.end(), {unsigned(f.x), unsigned(f.y), unsigned(f.z)});
  return true;
}

/// Glass triangles for peeling (world space, 4 floats each: position and surface number),
/// wound counter-clockwise seen from outside the solid.
struct GlassSoup {
  std::vector<float> data;
  void triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 outward, float surface) {
    if (glm::dot(glm::cross(b - a, c - a), outward) < 0.0f)
      std::swap(b, c);
    for (const glm::vec3& p : {a, b, c})
      data.insert(data.end(), {p.x, p.y, p.z, surface});
  }
};

GlassSoup glass_triangles(const SceneObject& object) {
  const glm::mat4 to_world(object_to_world(object.transform));
  const glm::mat3 normal_to_world = glm::transpose(glm::inverse(glm::mat3(to_world)));
  auto world = [&](glm::vec3 p) { return glm::vec3(to_world * glm::vec4(p, 1.0f)); };
  GlassSoup soup;
  const Shape& s = object.shape;
  if (s.type == ShapeType::kSlab) {
    const glm::vec3 h = 0.5f * glm::vec3(s.size.x, s.size.y, s.thickness);
    for (int axis = 0; axis < 3; ++axis) {
      const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
      const float surface = axis == 2 ? 0.0f : axis == 0 ? 1.0f : 2.0f;  // Z, X, Y pairs
      for (const float side : {-1.0f, 1.0f}) {
        glm::vec3 c[4];
        const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (int k = 0; k < 4; ++k) {
          c[k][axis] = side * h[axis];
          c[k][a1] = corners[k][0] * h[a1];
          c[k][a2] = corners[k][1] * h[a2];
          c[k] = world(c[k]);
        }
        glm::vec3 n(0.0f);
        n[axis] = side;
        const glm::vec3 outward = normal_to_world * n;
        soup.triangle(c[0], c[1], c[2], outward, surface);
        soup.triangle(c[0], c[2], c[3], outward, surface);
      }
    }
    return soup;
  }
  // Hollow cylinder: outer wall (0), inner wall (1, its outward side faces the axis), rims (2).
  const int n = 256;
  const float outer = s.radius, inner = s.radius - s.thickness, h = 0.5f * s.height;
  for (int i = 0; i < n; ++i) {
    const float a0 = 2.0f * kPi * float(i) / float(n), a1 = 2.0f * kPi * float(i + 1) / float(n);
    const glm::vec3 r0(std::sin(a0), 0.0f, std::cos(a0)), r1(std::sin(a1), 0.0f, std::cos(a1));
    const glm::vec3 mid = normal_to_world * glm::normalize(r0 + r1);
    for (int wall = 0; wall < 2; ++wall) {
      const float r = wall == 0 ? outer : inner;
      const glm::vec3 outward = wall == 0 ? mid : -mid;
      const glm::vec3 p00 = world(r * r0 + glm::vec3(0, -h, 0)),
                      p10 = world(r * r1 + glm::vec3(0, -h, 0)),
                      p11 = world(r * r1 + glm::vec3(0, h, 0)),
                      p01 = world(r * r0 + glm::vec3(0, h, 0));
      soup.triangle(p00, p10, p11, outward, float(wall));
      soup.triangle(p00, p11, p01, outward, float(wall));
    }
    for (const float side : {-1.0f, 1.0f}) {
      const glm::vec3 y(0.0f, side * h, 0.0f);
      const glm::vec3 outward = normal_to_world * glm::vec3(0.0f, side, 0.0f);
      const glm::vec3 p00 = world(inner * r0 + y), p10 = world(outer * r0 + y),
                      p11 = world(outer * r1 + y), p01 = world(inner * r1 + y);
      soup.triangle(p00, p10, p11, outward, 2.0f);
      soup.triangle(p00, p11, p01, outward, 2.0f);
    }
  }
  return soup;
}

/// The class of a sequence of peeled surface codes (shaders/glass_composite.frag's glass_class),
/// -1 for a pattern the displacement does not model (traced per pixel there).
int glass_class(ShapeType shape, const std::vector<int>& codes, bool trace_verge) {
  const size_t count = std::min<size_t>(codes.size(), 4);
  if (count == 0)
    return 0;
  if (shape == ShapeType::kSlab) {
    if (count == 2 && codes[0] % 2 == 0 && codes[1] == codes[0] + 1)
      return 1 + codes[0] / 2;
    return -1;
  }
  if (count == 4 && codes[0] == 0 && codes[1] == 3 && codes[2] == 2 && codes[3] == 1)
    return 4;
  if (count == 2 && codes[0] == 0 && codes[1] == 1)
    return trace_verge ? -1 : 5;
  if (count == 2 && codes[0] == 0 && codes[1] == 3)
    return 6;
  if (count == 2 && codes[0] == 2 && codes[1] == 1)
    return 7;
  return -1;
}

/// The plate of a slab's face pair `pair` (0: the Z faces, 1: X, 2: Y).
GlassPlate slab_plate(const SceneObject& object, int pair) {
  if (pair == 0)
    return glass_plate(object);
  const int axis = pair == 1 ? 0 : 1;
  const glm::dmat4 to_world = object_to_world(object.transform);
  const double half = 0.5 * (axis == 0 ? object.shape.size.x : object.shape.size.y);
  glm::dvec4 offset(0.0);
  offset[axis] = half;
  const glm::dvec3 a(to_world * (glm::dvec4(0, 0, 0, 1) + offset));
  const glm::dvec3 b(to_world * (glm::dvec4(0, 0, 0, 1) - offset));
  glm::dvec3 axis_vector(0.0);
  axis_vector[axis] = 1.0;
  const glm::dvec3 normal =
      glm::normalize(glm::transpose(glm::inverse(glm::dmat3(to_world))) * axis_vector);
  GlassPlate plate;
  plate.centre = glm::vec3(0.5 * (a + b));
  plate.normal = glm::vec3(normal);
  plate.thickness = float(std::abs(glm::dot(a - b, normal)));
  plate.ior = object.material.ior;
  return plate;
}

}  // namespace

GlassRenderer::GlassRenderer() = default;

GlassRenderer::~GlassRenderer() {
  release_targets();
  for (DrawObject& d : draws_) {
    glDeleteVertexArrays(1, &d.vertex_array);
    glDeleteBuffers(1, &d.buffer);
    glDeleteBuffers(1, &d.index_buffer);
  }
  for (GLuint* buffer : {&glass_buffer_, &opaque_buffer_})
    if (*buffer != 0)
      glDeleteBuffers(1, buffer);
  for (GLuint* array : {&glass_vertex_array_, &empty_vertex_array_})
    if (*array != 0)
      glDeleteVertexArrays(1, array);
  for (GLuint* texture : {&environment_, &shadow_maps_})
    if (*texture != 0)
      glDeleteTextures(1, texture);
  if (shadow_framebuffer_ != 0)
    glDeleteFramebuffers(1, &shadow_framebuffer_);
}

long long GlassRenderer::vertex_count() const {
  long long n = 0;
  for (const DrawObject& d : draws_)
    n += d.vertex_count;
  return n;
}

bool GlassRenderer::load(const Scene& scene, const std::filesystem::path& shader_dir,
                         const GlassSettings& settings, std::string& error) {
  scene_ = scene;
  for (size_t k = 0; k < scene.objects.size(); ++k) {
    const SceneObject& o = scene.objects[k];
    if (o.material.type == MaterialType::kMirror) {
      error = scene.filename + ": the glass method draws no mirrors (object \"" + o.name + "\")";
      return false;
    }
    if (o.material.type != MaterialType::kDielectric)
      continue;
    if (glass_object_ >= 0) {
      error = scene.filename + ": the glass method takes one glass object (\"" +
              scene.objects[size_t(glass_object_)].name + "\" and \"" + o.name + "\")";
      return false;
    }
    if (o.shape.type != ShapeType::kSlab && o.shape.type != ShapeType::kHollowCylinder) {
      error = scene.filename + ": the glass method's glass is a slab or a hollow cylinder (\"" +
              o.name + "\" is a " + shape_name(o.shape.type) + ")";
      return false;
    }
    glass_object_ = int(k);
  }
  if (glass_object_ < 0) {
    error = scene.filename + ": the glass method needs a dielectric slab or hollow cylinder";
    return false;
  }
  const SceneObject& glass = scene.objects[size_t(glass_object_)];
  if (glass.shape.type == ShapeType::kHollowCylinder) {
    GlassCylinder cylinder;
    glm::mat4 to_world;
    if (!glass_cylinder(glass, cylinder, to_world, error)) {
      error = scene.filename + ": " + error;
      return false;
    }
  }

  // Scene extent: the analytic shapes' bounds and the camera (meshes are added below).
  lo_ = hi_ = scene.camera.position;
  auto grow = [&](const glm::mat4& to_world, glm::vec3 olo, glm::vec3 ohi) {
    for (int c = 0; c < 8; ++c) {
      const glm::vec3 corner((c & 1) ? ohi.x : olo.x, (c & 2) ? ohi.y : olo.y,
                             (c & 4) ? ohi.z : olo.z);
      const glm::vec3 w(to_world * glm::vec4(corner, 1.0f));
      lo_ = glm::min(lo_, w);
      hi_ = glm::max(hi_, w);
    }
  };
  std::vector<TriangleSoup> mesh_soups(scene.meshes.size());
  std::vector<bool> mesh_loaded(scene.meshes.size(), false);
  for (const SceneObject& o : scene.objects) {
    const glm::mat4 to_world(object_to_world(o.transform));
    if (o.shape.type == ShapeType::kMesh) {
      const size_t m = size_t(o.shape.mesh);
      if (!mesh_loaded[m]) {
        if (!mesh_soup(scene.meshes[m].file, mesh_soups[m], error))
          return false;
        mesh_loaded[m] = true;
      }
      glm::vec3 olo(3e38f), ohi(-3e38f);
      for (const Vertex& v : mesh_soups[m].vertices) {
        olo = glm::min(olo, v.position);
        ohi = glm::max(ohi, v.position);
      }
      grow(to_world, olo, ohi);
    } else {
      glm::dvec3 olo, ohi;
      shape_bounds(o.shape, olo, ohi);
      grow(to_world, glm::vec3(olo), glm::vec3(ohi));
    }
  }
  extent_ = std::max(1e-3f, glm::length(hi_ - lo_));

  // Opaque objects: vertex arrays, and the analytic ones for reflected rays.
  std::vector<GpuOpaque> opaque;
  const float max_edge = settings.max_edge * extent_;
  for (size_t k = 0; k < scene.objects.size(); ++k) {
    const SceneObject& o = scene.objects[k];
    if (int(k) == glass_object_)
      continue;
    TriangleSoup tessellated;
    const TriangleSoup* soup = &tessellated;
    if (o.shape.type == ShapeType::kMesh) {
      soup = &mesh_soups[size_t(o.shape.mesh)];
    } else if (!tessellate(o.shape, max_edge, tessellated)) {
      error = scene.filename + ": the glass method cannot draw \"" + o.name + "\" (a " +
              shape_name(o.shape.type) + ") as an opaque object";
      return false;
    }
    if (o.shape.type != ShapeType::kMesh) {
      const glm::dmat4 to_world = object_to_world(o.transform);
      GpuOpaque g{};
      g.to_world = glm::mat4(to_world);
      g.to_object = glm::mat4(glm::inverse(to_world));
      g.shape = glm::vec4(o.shape.radius, o.shape.height, o.shape.thickness, 0.0f);
      g.size = glm::vec4(o.shape.size, 0.0f);
      g.color = glm::vec4(o.material.color, 1.0f);
      g.checker0 = glm::vec4(o.material.checker_colors[0], o.material.checker_scale.x);
      g.checker1 = glm::vec4(o.material.checker_colors[1], o.material.checker_scale.y);
      g.kind = glm::ivec4(int(o.shape.type), int(o.material.texture), 0, 0);
      opaque.push_back(g);
    }
    DrawObject d;
    d.object = int(k);
    d.index_count = GLsizei(soup->indices.size());
    d.vertex_count = GLsizei(soup->vertices.size());
    glCreateBuffers(1, &d.buffer);
    glNamedBufferStorage(d.buffer, GLsizeiptr(soup->vertices.size() * sizeof(Vertex)),
                         soup->vertices.data(), 0);
    glCreateBuffers(1, &d.index_buffer);
    glNamedBufferStorage(d.index_buffer, GLsizeiptr(soup->indices.size() * sizeof(unsigned)),
                         soup->indices.data(), 0);
    glCreateVertexArrays(1, &d.vertex_array);
    glVertexArrayVertexBuffer(d.vertex_array, 0, d.buffer, 0, sizeof(Vertex));
    glVertexArrayElementBuffer(d.vertex_array, d.index_buffer);
    for (GLuint attribute = 0; attribute < 3; ++attribute) {
      glEnableVertexArrayAttrib(d.vertex_array, attribute);
      glVertexArrayAttribFormat(d.vertex_array, attribute, attribute == 2 ? 2 : 3, GL_FLOAT,
                                GL_FALSE, attribute * 3 * sizeof(float));
      glVertexArrayAttribBinding(d.vertex_array, attribute, 0);
    }
    draws_.push_back(d);
  }
  opaque_count_ = int(opaque.size());
  glCreateBuffers(1, &opaque_buffer_);
  glNamedBufferStorage(opaque_buffer_,
                       GLsizeiptr(std::max<size_t>(1, opaque.size()) * sizeof(GpuOpaque)),
                       opaque.empty() ? nullptr : opaque.data(), 0);

  // The glass for peeling.
  const GlassSoup glass_soup = glass_triangles(glass);
  glass_vertex_count_ = GLsizei(glass_soup.data.size() / 4);
  glCreateBuffers(1, &glass_buffer_);
  glNamedBufferStorage(glass_buffer_, GLsizeiptr(glass_soup.data.size() * sizeof(float)),
                       glass_soup.data.data(), 0);
  glCreateVertexArrays(1, &glass_vertex_array_);
  glVertexArrayVertexBuffer(glass_vertex_array_, 0, glass_buffer_, 0, 4 * sizeof(float));
  glEnableVertexArrayAttrib(glass_vertex_array_, 0);
  glVertexArrayAttribFormat(glass_vertex_array_, 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(glass_vertex_array_, 0, 0);
  glEnableVertexArrayAttrib(glass_vertex_array_, 1);
  glVertexArrayAttribFormat(glass_vertex_array_, 1, 1, GL_FLOAT, GL_FALSE, 3 * sizeof(float));
  glVertexArrayAttribBinding(glass_vertex_array_, 1, 0);
  glCreateVertexArrays(1, &empty_vertex_array_);

  if (!upload_environment_texture(scene.environment, environment_, error))
    return false;

  if (!peel_program_.build(shader_dir, {"glass_peel.vert", "glass_peel.frag"}, "", error) ||
      !scene_program_.build(shader_dir, {"glass_scene.vert", "glass_scene.frag"}, "", error) ||
      !shadow_program_.build(shader_dir, {"glass_shadow.vert", "glass_shadow.frag"}, "", error) ||
      !composite_program_.build(shader_dir, {"fullscreen.vert", "glass_composite.frag"}, "",
                                error)) {
    return false;
  }

  // Shadow maps of the directional lights.
  const int lights = std::max<int>(1, int(std::min<size_t>(scene.lights.size(), kMaxLights)));
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &shadow_maps_);
  glTextureStorage3D(shadow_maps_, 1, GL_DEPTH_COMPONENT32F, settings.shadow_map_size,
                     settings.shadow_map_size, lights);
  glTextureParameteri(shadow_maps_, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTextureParameteri(shadow_maps_, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glTextureParameteri(shadow_maps_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(shadow_maps_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(shadow_maps_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(shadow_maps_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glCreateFramebuffers(1, &shadow_framebuffer_);
  render_shadow_maps();
  return true;
}

void GlassRenderer::render_shadow_maps() {
  light_view_projection_.assign(kMaxLights, glm::mat4(1.0f));
  const glm::vec3 centre = 0.5f * (lo_ + hi_);
  const float radius = 0.5f * glm::length(hi_ - lo_) + 1e-3f;
  GLint size[3];
  glGetTextureLevelParameteriv(shadow_maps_, 0, GL_TEXTURE_WIDTH, &size[0]);
  glBindFramebuffer(GL_FRAMEBUFFER, shadow_framebuffer_);
  glViewport(0, 0, size[0], size[0]);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(2.0f, 4.0f);
  glUseProgram(shadow_program_.id());
  for (size_t i = 0; i < scene_.lights.size() && i < size_t(kMaxLights); ++i) {
    const Light& light = scene_.lights[i];
    if (light.type != LightType::kDirectional)
      continue;
    const glm::vec3 d = glm::normalize(light.direction);
    const glm::vec3 up = std::abs(d.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::mat4 view = glm::lookAt(centre - 2.0f * radius * d, centre, up);
    light_view_projection_[i] =
        glm::ortho(-radius, radius, -radius, radius, radius, 3.0f * radius) * view;
    glNamedFramebufferTextureLayer(shadow_framebuffer_, GL_DEPTH_ATTACHMENT, shadow_maps_, 0,
                                   GLint(i));
    glNamedFramebufferDrawBuffer(shadow_framebuffer_, GL_NONE);
    glClear(GL_DEPTH_BUFFER_BIT);
    glUniformMatrix4fv(shadow_program_.uniform("u_light_view_projection"), 1, GL_FALSE,
                       glm::value_ptr(light_view_projection_[i]));
    for (const DrawObject& draw : draws_) {
      const glm::mat4 to_world(object_to_world(scene_.objects[size_t(draw.object)].transform));
      glUniformMatrix4fv(shadow_program_.uniform("u_to_world"), 1, GL_FALSE,
                         glm::value_ptr(to_world));
      glBindVertexArray(draw.vertex_array);
      glDrawElements(GL_TRIANGLES, draw.index_count, GL_UNSIGNED_INT, nullptr);
    }
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
}

void GlassRenderer::release_targets() {
  for (Target& t : layers_) {
    if (t.framebuffer != 0)
      glDeleteFramebuffers(1, &t.framebuffer);
    if (t.texture != 0)
      glDeleteTextures(1, &t.texture);
    if (t.depth != 0)
      glDeleteRenderbuffers(1, &t.depth);
    t = Target{};
  }
  if (class_framebuffer_ != 0)
    glDeleteFramebuffers(1, &class_framebuffer_);
  if (class_images_ != 0)
    glDeleteTextures(1, &class_images_);
  if (class_depth_ != 0)
    glDeleteRenderbuffers(1, &class_depth_);
  class_framebuffer_ = class_images_ = class_depth_ = 0;
  width_ = height_ = class_layers_ = 0;
}

bool GlassRenderer::ensure_targets(int width, int height, int class_layers) {
  if (width == width_ && height == height_ && class_layers <= class_layers_)
    return true;
  release_targets();
  bool complete = true;
  for (Target& t : layers_) {
    glCreateTextures(GL_TEXTURE_2D, 1, &t.texture);
    glTextureStorage2D(t.texture, 1, GL_RGBA32F, width, height);
    glCreateRenderbuffers(1, &t.depth);
    glNamedRenderbufferStorage(t.depth, GL_DEPTH_COMPONENT32F, width, height);
    glCreateFramebuffers(1, &t.framebuffer);
    glNamedFramebufferTexture(t.framebuffer, GL_COLOR_ATTACHMENT0, t.texture, 0);
    glNamedFramebufferRenderbuffer(t.framebuffer, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t.depth);
    complete = complete && glCheckNamedFramebufferStatus(t.framebuffer, GL_FRAMEBUFFER) ==
                               GL_FRAMEBUFFER_COMPLETE;
  }
  class_layers = std::max(class_layers, 1);
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &class_images_);
  glTextureStorage3D(class_images_, 1, GL_RGBA32F, width, height, class_layers);
  glCreateRenderbuffers(1, &class_depth_);
  glNamedRenderbufferStorage(class_depth_, GL_DEPTH_COMPONENT32F, width, height);
  glCreateFramebuffers(1, &class_framebuffer_);
  glNamedFramebufferRenderbuffer(class_framebuffer_, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                 class_depth_);
  width_ = width;
  height_ = height;
  class_layers_ = class_layers;
  return complete;
}

std::vector<int> GlassRenderer::classes_present(const Camera& camera, float aspect,
                                                bool trace_verge) const {
  // The straight eye lines of a grid of pixels against the exact glass: the same codes as the
  // peeling, hence the classes the frame needs.
  const SceneObject& glass = scene_.objects[size_t(glass_object_)];
  const glm::dmat4 to_world = object_to_world(glass.transform);
  const glm::dmat4 to_object = glm::inverse(to_world);
  std::set<int> classes = {0};
  const int n = 128;
  const int width = std::max(1, int(std::lround(n * aspect)));
  const double inner = double(glass.shape.radius) - double(glass.shape.thickness);
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < width; ++x) {
      const CameraRay ray = camera_ray(camera, width, n, {x + 0.5, y + 0.5});
      const glm::dvec3 o(to_object * glm::dvec4(ray.origin, 1.0));
      const glm::dvec3 d(to_object * glm::dvec4(ray.direction, 0.0));
      std::vector<int> codes;
      double t_min = 0.0;
      PrimitiveHit hit;
      while (codes.size() < 4 && intersect_shape(glass.shape, o, d, t_min, 1e30, hit)) {
        const glm::dvec3 p = o + hit.t * d;
        int surface;
        if (glass.shape.type == ShapeType::kSlab) {
          const glm::dvec3 a = glm::abs(hit.normal);
          surface = a.z >= a.x && a.z >= a.y ? 0 : a.x >= a.y ? 1 : 2;
        } else if (std::abs(hit.normal.y) > 0.5) {
          surface = 2;
        } else {
          const double r = std::sqrt(p.x * p.x + p.z * p.z);
          surface = std::abs(r - inner) < std::abs(r - double(glass.shape.radius)) ? 1 : 0;
        }
        codes.push_back(2 * surface + (glm::dot(d, hit.normal) < 0.0 ? 0 : 1));
        t_min = hit.t * (1.0 + 1e-9) + 1e-9;
      }
      const int c = glass_class(glass.shape.type, codes, trace_verge);
      if (c >= 0)
        classes.insert(c);
    }
  }
  return {classes.begin(), classes.end()};
}

void GlassRenderer::render(const Camera& camera, const GlassSettings& settings, Framebuffer& target,
                           glm::vec2 jitter, GlassStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  const int width = target.width(), height = target.height();
  const float aspect = float(width) / float(height);
  const std::vector<int> classes = classes_present(camera, aspect, settings.trace_verge);
  ensure_targets(width, height, int(classes.size()));
  const SceneObject& glass = scene_.objects[size_t(glass_object_)];

  const float far_plane = 4.0f * extent_ + glm::length(camera.target - camera.position);
  const float near_plane = 1e-4f * far_plane;
  const glm::mat4 view = glm::lookAt(camera.position, camera.target, camera.up);
  glm::mat4 projection =
      glm::perspective(glm::radians(camera.fov_degrees), aspect, near_plane, far_plane);
  projection = jittered_projection(projection, jitter, width, height);
  const glm::mat4 view_projection = projection * view;

  // 2. Depth peeling of the glass in front of the scene: up to 4 layers.
  const auto peel = [&](const glm::mat4& vp) {
    const auto peel_start = std::chrono::steady_clock::now();
    glUseProgram(peel_program_.id());
    glUniformMatrix4fv(peel_program_.uniform("u_view_projection"), 1, GL_FALSE, glm::value_ptr(vp));
    glBindVertexArray(glass_vertex_array_);
    glBindTextureUnit(1, class_images_);
    const float no_layer[4] = {-1.0f, 2.0f, 0.0f, 0.0f};
    for (int k = 0; k < 4; ++k) {
      glBindFramebuffer(GL_FRAMEBUFFER, layers_[k].framebuffer);
      glViewport(0, 0, width, height);
      glClearBufferfv(GL_COLOR, 0, no_layer);
      glClearDepth(1.0);
      glClear(GL_DEPTH_BUFFER_BIT);
      glUniform1i(peel_program_.uniform("u_first"), k == 0 ? 1 : 0);
      if (k > 0)
        glBindTextureUnit(0, layers_[k - 1].texture);
      glDrawArrays(GL_TRIANGLES, 0, glass_vertex_count_);
    }
    if (stats == nullptr)
      return 0.0;
    glFinish();
    return elapsed_ms(peel_start);
  };

  // 1. The opaque objects once per refraction class present, displaced (class 0 first: its depth
  //    is the scene's for the peeling).
  const GLuint sp = scene_program_.id();
  glUseProgram(sp);
  const auto& u = [&](const char* name) { return scene_program_.uniform(name); };
  glUniformMatrix4fv(u("u_view_projection"), 1, GL_FALSE, glm::value_ptr(view_projection));
  glUniform3fv(u("u_eye"), 1, &camera.position.x);
  glUniform1f(u("u_ior"), glass.material.ior);
  const int light_count = int(std::min<size_t>(scene_.lights.size(), kMaxLights));
  auto set_lights = [&](const ShaderProgram& program) {
    glUniform1i(program.uniform("u_light_count"), light_count);
    glUniform3fv(program.uniform("u_ambient"), 1, &scene_.ambient.x);
    if (light_count > 0) {
      std::vector<glm::vec4> direction;
      std::vector<glm::vec3> position, color;
      for (int i = 0; i < light_count; ++i) {
        const Light& l = scene_.lights[size_t(i)];
        direction.emplace_back(glm::normalize(l.direction),
                               l.type == LightType::kPoint ? 1.0f : 0.0f);
        position.push_back(l.position);
        color.push_back(l.color * l.intensity);
      }
      glUniform4fv(program.uniform("u_light_direction"), light_count, &direction[0].x);
      glUniform3fv(program.uniform("u_light_position"), light_count, &position[0].x);
      glUniform3fv(program.uniform("u_light_color"), light_count, &color[0].x);
      glUniformMatrix4fv(program.uniform("u_light_view_projection"), light_count, GL_FALSE,
                         glm::value_ptr(light_view_projection_[0]));
    }
    glBindTextureUnit(6, shadow_maps_);
  };
  set_lights(scene_program_);
  GlassCylinder cylinder;
  glm::mat4 cylinder_to_world(1.0f);
  if (glass.shape.type == ShapeType::kHollowCylinder) {
    std::string ignored;
    glass_cylinder(glass, cylinder, cylinder_to_world, ignored);
    const glm::mat4 to_object = glm::inverse(cylinder_to_world);
    glUniformMatrix4fv(u("u_cylinder_to_object"), 1, GL_FALSE, glm::value_ptr(to_object));
    glUniformMatrix4fv(u("u_cylinder_to_world"), 1, GL_FALSE, glm::value_ptr(cylinder_to_world));
    glUniform1f(u("u_outer_radius"), cylinder.outer_radius);
    glUniform1f(u("u_inner_radius"), cylinder.inner_radius);
  }
  int layer_of_class[kGlassClasses];
  std::fill(layer_of_class, layer_of_class + kGlassClasses, -1);
  const float no_hit[4] = {0.0f, 0.0f, 0.0f, 2.0f};
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  double peel_ms = 0.0;
  for (size_t i = 0; i < classes.size(); ++i) {
    const int c = classes[i];
    if (i == 1)
      peel_ms = peel(view_projection);
    glUseProgram(sp);
    glBindFramebuffer(GL_FRAMEBUFFER, class_framebuffer_);
    glViewport(0, 0, width, height);
    layer_of_class[c] = int(i);
    glNamedFramebufferTextureLayer(class_framebuffer_, GL_COLOR_ATTACHMENT0, class_images_, 0,
                                   GLint(i));
    glNamedFramebufferDrawBuffer(class_framebuffer_, GL_COLOR_ATTACHMENT0);
    glClearBufferfv(GL_COLOR, 0, no_hit);
    glClear(GL_DEPTH_BUFFER_BIT);
    int kind = 0;
    if (c >= 1 && c <= 3) {
      kind = 1;
      const GlassPlate plate = slab_plate(glass, c - 1);
      glUniform3fv(u("u_plate_centre"), 1, &plate.centre.x);
      glUniform3fv(u("u_plate_normal"), 1, &plate.normal.x);
      glUniform1f(u("u_plate_thickness"), plate.thickness);
    } else if (c >= 4) {
      kind = 2;
      glUniform1i(u("u_path"), c - 4);
    }
    glUniform1i(u("u_glass"), kind);
    for (const DrawObject& draw : draws_) {
      const SceneObject& o = scene_.objects[size_t(draw.object)];
      const glm::dmat4 to_world_d = object_to_world(o.transform);
      const glm::mat4 to_world(to_world_d);
      const glm::mat3 normal_to_world(glm::transpose(glm::inverse(glm::dmat3(to_world_d))));
      glUniformMatrix4fv(u("u_to_world"), 1, GL_FALSE, glm::value_ptr(to_world));
      glUniformMatrix3fv(u("u_normal_to_world"), 1, GL_FALSE, glm::value_ptr(normal_to_world));
      glUniform1i(u("u_smooth"),
                  o.shape.type != ShapeType::kMesh || o.shape.smooth_normals ? 1 : 0);
      glUniform1i(u("u_texture"), int(o.material.texture));
      glUniform3fv(u("u_color"), 1, &o.material.color.x);
      const glm::vec4 c0(o.material.checker_colors[0], o.material.checker_scale.x);
      const glm::vec4 c1(o.material.checker_colors[1], o.material.checker_scale.y);
      glUniform4fv(u("u_checker0"), 1, &c0.x);
      glUniform4fv(u("u_checker1"), 1, &c1.x);
      glBindVertexArray(draw.vertex_array);
      glDrawElements(GL_TRIANGLES, draw.index_count, GL_UNSIGNED_INT, nullptr);
    }
  }
  if (classes.size() == 1)
    peel_ms = peel(view_projection);
  double scene_ms = 0.0;
  if (stats != nullptr) {
    glFinish();
    scene_ms = elapsed_ms(start) - peel_ms;
  }

  // 3. Composite: each pixel from its class's image, Fresnel on top.
  target.bind();
  glDisable(GL_DEPTH_TEST);
  const GLuint cp = composite_program_.id();
  glUseProgram(cp);
  const auto& v = [&](const char* name) { return composite_program_.uniform(name); };
  for (int k = 0; k < 4; ++k)
    glBindTextureUnit(GLuint(k), layers_[k].texture);
  glBindTextureUnit(4, class_images_);
  glBindTextureUnit(5, environment_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, opaque_buffer_);
  set_lights(composite_program_);
  glUniform1iv(v("u_layer_of_class"), kGlassClasses, layer_of_class);
  const glm::dmat4 glass_to_world = object_to_world(glass.transform);
  const glm::mat4 glass_to_object(glm::inverse(glass_to_world));
  glUniform1i(v("u_glass_shape"), int(glass.shape.type));
  glUniform4f(v("u_glass_params"), glass.shape.radius, glass.shape.height, glass.shape.thickness,
              0.0f);
  glUniform3fv(v("u_glass_size"), 1, &glass.shape.size.x);
  glUniformMatrix4fv(v("u_glass_to_object"), 1, GL_FALSE, glm::value_ptr(glass_to_object));
  glUniform1f(v("u_ior"), glass.material.ior);
  glUniform3fv(v("u_absorption"), 1, &glass.material.absorption.x);
  glUniform1i(v("u_fresnel"), settings.fresnel ? 1 : 0);
  glUniform1i(v("u_trace_verge"), settings.trace_verge ? 1 : 0);
  glUniform1f(v("u_epsilon"), 1e-5f * extent_);
  glUniformMatrix4fv(v("u_view_projection"), 1, GL_FALSE, glm::value_ptr(view_projection));
  glUniform1f(v("u_near"), near_plane);
  glUniform1f(v("u_far"), far_plane);
  glUniform1f(v("u_scene_extent"), extent_);
  glUniform1i(v("u_opaque_count"), opaque_count_);
  glUniform1i(v("u_has_meshes"), int(draws_.size()) > opaque_count_ ? 1 : 0);
  set_environment_uniforms(composite_program_, scene_.environment);
  set_camera_ray_uniforms(composite_program_, camera, width, height, jitter);
  glBindVertexArray(empty_vertex_array_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  if (stats != nullptr) {
    glFinish();
    stats->milliseconds += elapsed_ms(start);
    stats->peel_milliseconds += peel_ms;
    stats->scene_milliseconds += scene_ms;
    stats->class_images = int(classes.size());
    stats->vertices = vertex_count();
  }
}

Image GlassRenderer::render_image(int width, int height, const GlassSettings& settings,
                                  GlassStats* stats) {
  return render_supersampled(width, height, settings.samples_per_pixel,
                             [&](Framebuffer& target, glm::vec2 jitter) {
                               render(scene_.camera, settings, target, jitter, stats);
                             });
}

bool GlassRenderer::reload_shaders_if_changed(std::string& error) {
  std::string e[4];
  const bool a = peel_program_.reload_if_changed(e[0]);
  const bool b = scene_program_.reload_if_changed(e[1]);
  const bool c = shadow_program_.reload_if_changed(e[2]);
  const bool d = composite_program_.reload_if_changed(e[3]);
  error = e[0] + e[1] + e[2] + e[3];
  return (a || b || c || d) && error.empty();
}

}  // namespace gfield
