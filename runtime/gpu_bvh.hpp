#pragma once
// The meshes' BVHs on the GPU (exact tracing beside the geometry field). For every
// asset, the BVH of its mesh file (geometry/mesh_bvh.hpp over the rasterised source mesh, three
// vertices per triangle, read back from its vertex buffer) packed into the contract's storage
// buffers, one BVH after another: BUFFER_BVH_NODES (GpuBvhNode), BUFFER_BVH_TRIANGLES
// (GpuBvhTriangle, leaf order) and BUFFER_BVH_SHADING (GpuBvhShading, the same order). Node
// indices are global: a leaf's first triangle and an inner node's left child already include
// the offsets of the BVHs before it. shaders/lib/gpu_bvh.glsl reads them.

#include <cstddef>
#include <vector>

#include "runtime/gl_object.hpp"

namespace gfield {

struct GpuAsset;

class GpuBvhs {
 public:
  /// Builds the BVH of every asset's source mesh (uploaded already) and uploads all of them;
  /// sets each asset's bvh_root (-1 for an asset without triangles) and bvh_bytes.
  void build(std::vector<GpuAsset>& assets);
  /// Binds the three buffers to their contract slots (empty buffers before build()).
  void bind() const;
  /// The three buffers (BUFFER_BVH_NODES, BUFFER_BVH_TRIANGLES, BUFFER_BVH_SHADING).
  GLuint nodes() const { return nodes_.id(); }
  GLuint triangles() const { return triangles_.id(); }
  GLuint shading() const { return shading_.id(); }
  /// GPU bytes of the three buffers.
  size_t bytes() const { return bytes_; }
  /// Wall time of the last build (building and packing; the uploads included).
  double build_seconds() const { return build_seconds_; }

 private:
  GlBuffer nodes_;
  GlBuffer triangles_;
  GlBuffer shading_;
  size_t bytes_ = 0;
  double build_seconds_ = 0.0;
};

}  // namespace gfield
