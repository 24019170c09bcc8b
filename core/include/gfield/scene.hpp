#pragma once
// Scenes: the JSON format of docs/scenes.md, read into plain structs that both the reference
// ray tracer (preprocess/) and the OpenGL runtime use. No Embree, no GL here.
//
// Paths in a scene file resolve relative to the scene file; the structs hold resolved paths.
// World space is right-handed, +Y up; lengths in scene units; angles in degrees in the file.

#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gfield/confined_path.hpp"
#include "gfield/environment.hpp"
#include "gfield/gpu_contract.hpp"

namespace gfield {

/// Pinhole camera. `fov_degrees` is the vertical field of view; the aspect ratio is the image's.
struct Camera {
  glm::vec3 position{0.0f, 0.0f, 5.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_degrees = 45.0f;
};

/// A world-space ray through continuous pixel coordinates (x right from the left edge, y down
/// from the top edge, both in pixels: the centre of pixel (i, j) is (i + 0.5, j + 0.5)).
/// The same projection as glm::lookAt + glm::perspective(fov, width / height).
struct CameraRay {
  glm::dvec3 origin;
  glm::dvec3 direction;  ///< unit
};
CameraRay camera_ray(const Camera& camera, int width, int height, glm::dvec2 pixel);

/// Object-space shapes. Every shape is centred on the origin before its transform.
/// Shape kinds; the numbers are the shaders' SHAPE_* codes (shaders/lib/contract.glsl).
enum class ShapeType {
  kMesh = gpu::SHAPE_MESH,
  kSphere = gpu::SHAPE_SPHERE,
  kQuad = gpu::SHAPE_QUAD,
  kBox = gpu::SHAPE_BOX,
  kCylinder = gpu::SHAPE_CYLINDER,
  kSlab = gpu::SHAPE_SLAB,
  kHollowCylinder = gpu::SHAPE_HOLLOW_CYLINDER,
};

struct Shape {
  ShapeType type = ShapeType::kSphere;
  int mesh = -1;               ///< kMesh: index into Scene::meshes
  bool smooth_normals = true;  ///< kMesh: interpolated vertex normals (else face normals)
  float radius = 1.0f;         ///< sphere; cylinder; hollow cylinder: the OUTER radius
  float height = 2.0f;         ///< cylinder, hollow cylinder: extent along Y (from -h/2 to h/2)
  glm::vec3 size{2.0f};        ///< box: extents along X, Y, Z; quad, slab: X, Y extents (z unused)
  float thickness = 0.1f;  ///< slab: extent along Z; hollow cylinder: wall (inner = radius - it)
};

/// True for shapes that bound a solid (everything but the quad): dielectrics need one.
bool shape_is_closed(ShapeType type);
/// The scene-file name of a shape type ("mesh", "sphere", "quad", "box", "cylinder", "slab",
/// "hollow-cylinder").
const char* shape_name(ShapeType type);

/// Object -> world: translate * rotate_z * rotate_y * rotate_x * scale (scale applied first, then
/// rotation about X, then Y, then Z, then translation).
struct Transform {
  glm::vec3 translate{0.0f};
  glm::vec3 rotate_degrees{0.0f};
  glm::vec3 scale{1.0f};
};
glm::dmat4 object_to_world(const Transform& transform);
/// The Transform of an affine `matrix` (no perspective): translation, rotation (degrees) and
/// positive scale factors with object_to_world(result) ~ matrix. `residual` receives the largest
/// difference of the recomposed matrix's linear part from `matrix`'s, relative to its largest
/// column (0 without shear). False when the linear part is singular or mirrors (determinant
/// <= 0).
bool transform_from_matrix(const glm::dmat4& matrix, Transform& transform, double& residual);

/// Object-space bounds of an analytic shape (zero for meshes: their bounds come from the file).
void shape_bounds(const Shape& shape, glm::dvec3& lo, glm::dvec3& hi);
/// The largest |coordinate| of the box [lo, hi] mapped by the affine `m` (reached at a corner):
/// an object's reach in world coordinates is box_reach(object_to_world(t), lo, hi).
double box_reach(const glm::dmat4& m, glm::dvec3 lo, glm::dvec3 hi);

/// Material and texture kinds; the numbers are the shaders' MATERIAL_* and TEXTURE_* codes.
enum class MaterialType {
  kDiffuse = gpu::MATERIAL_DIFFUSE,
  kMirror = gpu::MATERIAL_MIRROR,
  kDielectric = gpu::MATERIAL_DIELECTRIC,
};
enum class TextureType {
  kNone = gpu::TEXTURE_NONE,
  kChecker = gpu::TEXTURE_CHECKER,
  kColorChart = gpu::TEXTURE_COLOR_CHART,
  kMesh = gpu::TEXTURE_MESH,  ///< meshes: their own base colour (texture, vertex, material colours)
};

struct Material {
  MaterialType type = MaterialType::kDiffuse;
  /// Diffuse albedo (texture kNone) or mirror tint (reflectance per channel).
  glm::vec3 color{0.8f};
  TextureType texture = TextureType::kNone;
  std::array<glm::vec3, 2> checker_colors{glm::vec3(0.9f), glm::vec3(0.1f)};
  glm::vec2 checker_scale{8.0f};  ///< squares along u and v of the texture coordinates
  float ior = 1.5f;               ///< dielectric: index of refraction (outside is air, 1)
  std::string ior_preset;         ///< the preset name when the file gave one
  glm::vec3 absorption{0.0f};     ///< dielectric: Beer–Lambert coefficient per scene unit
  /// A diffuse mesh whose scene gave no "texture": kMesh when the mesh carries a base colour,
  /// else kNone (decided once the mesh is read: geometry/scene_file.hpp).
  bool texture_by_mesh = false;
  /// The scene gave no "color": 1 with the mesh's own base colour, else 0.8.
  bool default_color = false;
};

/// Albedo of a textured diffuse material at texture coordinates uv in [0,1]^2 (docs/scenes.md:
/// checker squares; colour chart = the 24 patches of the ColorChecker, 6 x 4, v = 1 at the top
/// row, linear sRGB values, black gaps between patches).
glm::vec3 texture_albedo(const Material& material, glm::vec2 uv);

enum class LightType { kDirectional, kPoint };

/// Diffuse surfaces get albedo * (ambient + sum of lights color * intensity * max(0, N.L) / d^2)
/// (d = 1 for directional lights), with shadow rays blocked by diffuse and mirror objects.
struct Light {
  LightType type = LightType::kDirectional;
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  ///< directional: the way the light travels (unit)
  glm::vec3 position{0.0f};                ///< point
  glm::vec3 color{1.0f};
  float intensity = 1.0f;
};

/// One mesh file (for a glTF file: one mesh of it) and its precomputed assets (empty path: not
/// found / not given).
struct MeshAsset {
  std::string file;
  std::string part;   ///< glTF: the mesh's index in the file, "#INDEX" ("" for other formats)
  std::string asset;  ///< NAME of its assets NAME.gimage.exr, NAME.gfield.exr: the mesh file's
                      ///< stem, for a glTF mesh "STEM.INDEX-MESHNAME" (gltf_scene.hpp)
  std::string geometry_image;  ///< NAME.gimage.exr beside the mesh, or named by the scene
  std::string geometry_field;  ///< NAME.gfield.exr beside the mesh, or named by the scene
  /// Whether reading the mesh file may read files outside its folder (glTF buffers and images,
  /// material libraries, textures): the scene was read with --allow-outside-paths.
  OutsidePaths outside_paths = OutsidePaths::kRefused;
};

struct SceneObject {
  std::string name;
  Shape shape;
  Transform transform;
  Material material;
};

/// A glTF file a JSON scene includes as one object (`"shape": "gltf"`): its meshes, placed by
/// its nodes and then by `transform`, with their own materials (geometry/scene_file.hpp
/// expands it into objects).
struct SceneInclude {
  std::string file;  ///< the glTF file (resolved)
  std::string name;
  Transform transform;
  size_t position = 0;  ///< the objects it becomes go before Scene::objects[position]
  std::string where;    ///< "SCENE:LINE:COLUMN: objects[I]", for messages
};

struct Scene {
  std::string filename;  ///< the scene file
  std::string purpose;   ///< one line: what the scene is for
  Camera camera;
  int width = 512;
  int height = 512;
  EnvironmentDesc environment;
  glm::vec3 ambient{0.0f};
  std::vector<Light> lights;
  std::vector<MeshAsset> meshes;  ///< each file once; objects refer to it by index (instances)
  std::vector<SceneObject> objects;
  std::vector<SceneInclude> includes;  ///< glTF files not expanded yet (core's parser only)
};

/// Reads and validates a scene file. False with "FILE:LINE:COLUMN: what: problem" for malformed
/// JSON, unknown keys, wrong types, unknown material/shape/preset names, missing files, files
/// outside the scene's root (unless `outside` is kAllowed: confined_path.hpp), negative or zero
/// sizes, a dielectric on a quad, a degenerate camera, and values out of range (docs/scenes.md,
/// "Limits"): any number beyond +-1e15, colours and intensities outside [0, 1e6], scale factors
/// and indices of refraction outside [1e-6, 1e6], an analytic shape reaching beyond +-1e15 after
/// its transform, more than kMaxSceneObjects objects or kMaxSceneLights lights, JSON nested
/// deeper than kMaxJsonDepth, a file above kMaxSceneFileBytes.
bool load_scene(const std::string& filename, Scene& scene, std::string& error,
                OutsidePaths outside = OutsidePaths::kRefused);

/// Points every mesh of `scene` at the assets found in folder `dir` (DIR/NAME.gimage.exr and
/// DIR/NAME.gfield.exr for MeshAsset::asset NAME, the stem of mesh file NAME.EXT, as `gfield
/// build MESH -o DIR/NAME` writes them); those found there take precedence over the ones beside
/// the mesh or named by the scene. False with "DIR: not a folder" when `dir` is not one.
bool use_asset_folder(const std::string& dir, Scene& scene, std::string& error);

/// The same from text; `filename` names the file in errors and is where relative paths start.
bool parse_scene(const std::string& text, const std::string& filename, Scene& scene,
                 std::string& error, OutsidePaths outside = OutsidePaths::kRefused);

}  // namespace gfield
