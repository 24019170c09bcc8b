#pragma once
// What gfield accepts from files (docs/formats.md, "Limits"). Every reader checks header counts
// against these maxima and against the file's size before it allocates or loops, and checks the
// numbers it reads against these ranges; anything outside is an error naming the file, the place
// and the value.

#include <cstddef>
#include <cstdint>

namespace gfield {

/// Largest |coordinate| accepted anywhere: mesh vertices, boxes, geometry-image positions, scene
/// positions and sizes, and world bounds after an object's transform (scene units). Far inside
/// float range, and far inside the |origin| <= 1.8e18 that Embree's ray checks allow, so that no
/// ray gfield casts with Embree is invalid.
inline constexpr double kMaxCoordinate = 1e15;
/// Largest |coordinate| in a gfield asset: boxes, geometry-image positions, parameterised meshes
/// (a mesh within kMaxCoordinate gets a box padded by a percent of its diagonal, within this).
/// Distances of thickness maps are at most kMaxAssetDistance.
inline constexpr double kMaxAssetCoordinate = 1e16;
inline constexpr double kMaxAssetDistance = 1e17;
/// Meshes that become assets (gfield image, build): the diagonal of the bounding box in
/// [kMinAssetDiagonal, kMaxAssetDiagonal] and no coordinate farther from the origin than
/// kMaxAssetOffsetRatio diagonals. Outside, float casts and float positions lose the surface:
/// spot 5e-12 across crashed the cast, 2.6e-15 across got no hit, 2.6e14 across 94% of the box
/// rays' hits right (99% within the range); 1,000 diagonals from the origin 79%, 100 as at the
/// origin, where float positions are 1.2e-5 of the diagonal apart, below the geometry image's
/// error (docs/reliability.md). Margins: 26x below, 26x above.
inline constexpr double kMinAssetDiagonal = 1e-9;
inline constexpr double kMaxAssetDiagonal = 1e12;
inline constexpr double kMaxAssetOffsetRatio = 100.0;
/// Geometry-image normals are unit vectors: each component within +-kMaxNormalComponent.
inline constexpr double kMaxNormalComponent = 2.0;

/// Mesh files (OBJ, PLY, OFF, STL): bytes, vertices, triangles after fan triangulation, corners of
/// one polygon.
inline constexpr std::uint64_t kMaxMeshFileBytes = std::uint64_t(2) << 30;
inline constexpr std::int64_t kMaxMeshVertices = 2'000'000'000;
inline constexpr std::int64_t kMaxMeshTriangles = 2'000'000'000;
inline constexpr std::int64_t kMaxPolygonCorners = 65'536;

/// Texture coordinates of meshes (OBJ vt, PLY u v, glTF TEXCOORD_0): finite, within +-this
/// (textures repeat; beyond it a float uv no longer resolves a texel of a 4096^2 texture).
inline constexpr double kMaxTextureCoordinate = 1e4;
/// Colours read from files (vertex and material colours, geometry-image albedo): each component
/// finite and in [0, kMaxColorComponent].
inline constexpr double kMaxColorComponent = 1e6;
/// One mesh file's materials and textures (OBJ mtllib/usemtl, glTF materials and images), and
/// the bytes of one material library (.mtl).
inline constexpr std::size_t kMaxMeshMaterials = 65'536;
inline constexpr std::size_t kMaxMeshTextures = 1'024;
inline constexpr std::uint64_t kMaxMaterialLibraryBytes = std::uint64_t(16) << 20;

/// glTF files (.gltf, .glb) and the buffers they name: bytes as for meshes (kMaxMeshFileBytes);
/// nodes, meshes, primitives and every other array of the document at most kMaxGltfElements (a
/// node hierarchy may be one chain of them all: its checks take time linear in the nodes).
inline constexpr std::size_t kMaxGltfElements = 1'000'000;

/// The textures of one mesh decode to at most this many bytes together, as linear float RGB (12
/// bytes a pixel: one 13,377^2 texture, or ten of 4096^2): each texture's claimed size is checked
/// against what is left before it is decoded. Commands that need no pixels (`gfield info`) read
/// the textures' headers only.
inline constexpr std::uint64_t kMaxMeshTextureBytes = std::uint64_t(2) << 30;

/// Scale factors of transforms (JSON scenes, glTF nodes): in [kMinScaleFactor, kMaxScaleFactor].
inline constexpr double kMinScaleFactor = 1e-6;
inline constexpr double kMaxScaleFactor = 1e6;
/// Indices of refraction (JSON scenes, glTF KHR_materials_ior): in [kMinIor, kMaxIor].
inline constexpr double kMinIor = 1e-6;
inline constexpr double kMaxIor = 1e6;

/// Geometry images (and thickness maps): n x n with n at most this.
inline constexpr int kMaxGeometryImageSide = 8192;
/// Pictures read as environment maps or compared (EXR, PNG, HDR): pixels per side and in all.
inline constexpr int kMaxPictureSide = 65'536;
inline constexpr std::uint64_t kMaxPictureFileBytes = std::uint64_t(1) << 30;
inline constexpr std::int64_t kMaxPicturePixels = std::int64_t(1) << 28;
/// A compressed image cannot hold more than this many bytes of pixels per byte of file (zlib's
/// ratio is below 1,100; OpenEXR's other codecs and PNG's, HDR's RLE stay below it): a header
/// claiming more pixels than its file can hold is refused before anything is allocated.
inline constexpr std::uint64_t kMaxCompressionRatio = 1100;

/// Scene files: bytes, objects, lights, JSON nesting.
inline constexpr std::uint64_t kMaxSceneFileBytes = std::uint64_t(16) << 20;
inline constexpr std::size_t kMaxSceneObjects = 10'000;
inline constexpr std::size_t kMaxSceneLights = 1'000;
inline constexpr int kMaxJsonDepth = 64;

}  // namespace gfield
