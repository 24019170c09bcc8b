#include "runtime/gpu_bvh.hpp"

#include <algorithm>
#include <bit>

#include "geometry/mesh_bvh.hpp"
#include "gfield/gpu_contract.hpp"
#include "gfield/stopwatch.hpp"
#include "runtime/gpu_assets.hpp"

namespace gfield {
namespace {

/// The three packed arrays of every BVH.
struct Packed {
  std::vector<gpu::GpuBvhNode> nodes;
  std::vector<gpu::GpuBvhTriangle> triangles;
  std::vector<gpu::GpuBvhShading> shading;
};

float int_bits(int value) {
  return std::bit_cast<float>(value);
}

/// The vertices of `mesh` (three per triangle), read back from the GPU.
std::vector<GpuVertex> read_vertices(const GpuMesh& mesh) {
  std::vector<GpuVertex> vertices(size_t(std::max(0, mesh.vertex_count)));
  if (!vertices.empty())
    glGetNamedBufferSubData(mesh.vertices.id(), 0, GLsizeiptr(vertices.size() * sizeof(GpuVertex)),
                            vertices.data());
  return vertices;
}

/// Appends the BVH of triangles (3f, 3f + 1, 3f + 2) of `vertices` to `packed`; returns its root
/// (-1: no triangles).
int pack_bvh(const std::vector<GpuVertex>& vertices, Packed& packed) {
  const size_t count = vertices.size() / 3;
  std::vector<glm::vec3> positions(vertices.size());
  std::vector<glm::ivec3> triangles(count);
  for (size_t c = 0; c < vertices.size(); ++c)
    positions[c] = vertices[c].position;
  for (size_t f = 0; f < count; ++f)
    triangles[f] = glm::ivec3(3 * int(f), 3 * int(f) + 1, 3 * int(f) + 2);
  const MeshBvh bvh = build_mesh_bvh(positions, triangles);
  if (bvh.nodes.empty())
    return -1;
  const int node_base = int(packed.nodes.size()), slot_base = int(packed.triangles.size());
  for (const BvhNode& n : bvh.nodes) {
    const int first = n.first + (n.count > 0 ? slot_base : node_base);
    packed.nodes.push_back({glm::vec4(n.lo, int_bits(first)), glm::vec4(n.hi, int_bits(n.count))});
  }
  for (const int f : bvh.order) {
    const GpuVertex* v = &vertices[3 * size_t(f)];
    packed.triangles.push_back({glm::vec4(v[0].position, v[0].base.a),
                                glm::vec4(v[1].position - v[0].position, 0.0f),
                                glm::vec4(v[2].position - v[0].position, 0.0f)});
    packed.shading.push_back(
        {glm::vec4(v[0].normal, v[0].uv.x), glm::vec4(v[1].normal, v[1].uv.x),
         glm::vec4(v[2].normal, v[2].uv.x), glm::vec4(glm::vec3(v[0].base), v[0].uv.y),
         glm::vec4(glm::vec3(v[1].base), v[1].uv.y), glm::vec4(glm::vec3(v[2].base), v[2].uv.y)});
  }
  return node_base;
}

template <class T>
size_t upload(GlBuffer& buffer, const std::vector<T>& data) {
  buffer.make();
  const size_t bytes = std::max<size_t>(1, data.size()) * sizeof(T);
  glNamedBufferStorage(buffer.id(), GLsizeiptr(bytes), data.empty() ? nullptr : data.data(), 0);
  return bytes;
}

}  // namespace

void GpuBvhs::build(std::vector<GpuAsset>& assets) {
  const Stopwatch clock;
  Packed packed;
  for (GpuAsset& asset : assets) {
    const size_t nodes = packed.nodes.size(), triangles = packed.triangles.size();
    asset.bvh_root = pack_bvh(read_vertices(asset.source), packed);
    asset.bvh_bytes = (packed.nodes.size() - nodes) * sizeof(gpu::GpuBvhNode) +
                      (packed.triangles.size() - triangles) *
                          (sizeof(gpu::GpuBvhTriangle) + sizeof(gpu::GpuBvhShading));
  }
  bytes_ = upload(nodes_, packed.nodes) + upload(triangles_, packed.triangles) +
           upload(shading_, packed.shading);
  build_seconds_ = clock.seconds();
}

void GpuBvhs::bind() const {
  if (!nodes_)
    return;
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BUFFER_BVH_NODES, nodes_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BUFFER_BVH_TRIANGLES, triangles_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BUFFER_BVH_SHADING, shading_.id());
}

}  // namespace gfield
