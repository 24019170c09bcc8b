#include "preprocess/albedo_resample.hpp"

namespace gfield {

AlbedoSource::AlbedoSource(const TriangleMesh& input, const MeshAppearance& appearance,
                           const TriangleMesh& repaired, const std::vector<int>& source_face)
    : input_(input), appearance_(appearance) {
  source_.assign(repaired.triangles.size(), -1);
  corners_.assign(repaired.triangles.size(), glm::ivec3(-1));
  for (size_t f = 0; f < repaired.triangles.size() && f < source_face.size(); ++f) {
    const int s = source_face[f];
    if (s < 0 || size_t(s) >= input.triangles.size())
      continue;
    glm::ivec3 map(-1);
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j)
        if (input.positions[size_t(input.triangles[size_t(s)][j])] ==
            repaired.positions[size_t(repaired.triangles[f][k])])
          map[k] = j;
    if (map.x >= 0 && map.y >= 0 && map.z >= 0 && map.x != map.y && map.y != map.z &&
        map.x != map.z) {
      source_[f] = s;
      corners_[f] = map;
    }
  }
}

bool AlbedoSource::sample(int face, glm::dvec3 w, glm::dvec3 dw_di, glm::dvec3 dw_dj,
                          glm::vec3& color) const {
  const int s = source_[size_t(face)];
  if (s < 0)
    return false;
  const glm::ivec3 map = corners_[size_t(face)];
  glm::dvec3 wi(0.0), di(0.0), dj(0.0);
  for (int k = 0; k < 3; ++k) {
    wi[map[k]] = w[k];
    di[map[k]] = dw_di[k];
    dj[map[k]] = dw_dj[k];
  }
  const glm::vec2 uv = uv_at(appearance_, size_t(s), wi);
  const glm::vec2 du = uv_at(appearance_, size_t(s), wi + di) - uv;
  const glm::vec2 dv = uv_at(appearance_, size_t(s), wi + dj) - uv;
  color = footprint_color(input_, appearance_, size_t(s), wi, du, dv);
  return true;
}

}  // namespace gfield
