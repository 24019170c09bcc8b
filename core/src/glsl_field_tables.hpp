#pragma once
// The fetches that shaders/lib/field_lines.glsl makes, over the CPU copy of a field: the
// nearest-hit table, the line table's words and the interior hits. The base of the structs that
// compile field_lines.glsl (field_lines.cpp) and field_lookup.glsl (field_lookup.cpp) as C++.

#include <cstdint>

#include <glm/glm.hpp>

#include "gfield/check.hpp"
#include "gfield/field_lookup.hpp"
#include "gfield/geometry_field.hpp"

namespace gfield {

struct GlslFieldTables {
  const GeometryField& field;
  LookupWork* work = nullptr;  ///< where the fetches are counted (null: nowhere)

  /// Counts `n` of work `kind` (the contract's WORK_*), as the shaders' GF_COUNT / WORK_ADD.
  void count_work(int kind, int n) const {
    if (work != nullptr) {
      work->counts[size_t(kind)] += uint64_t(n);
    }
  }
  int gf_samples_per_side() const { return field.samples_per_side; }
  glm::vec2 gf_field_nearest_texel(int entry, int column) const {
    count_work(gpu::WORK_FIELD_FETCHES, 1);
    return field.nearest[field_nearest_index(field, entry, column)];
  }
  uint32_t gf_field_word(int i) const {
    count_work(gpu::WORK_FIELD_FETCHES, 1);
    GF_DCHECK(i >= 0 && size_t(i) < field.lines.size(), "word outside the line table");
    return field.lines[size_t(i)];
  }
  glm::vec2 gf_field_interior_texel(int i) const {
    count_work(gpu::WORK_FIELD_FETCHES, 1);
    GF_DCHECK(i >= 0 && size_t(i) < field.interior.size(), "interior hit outside the field's");
    return field.interior[size_t(i)];
  }
};

}  // namespace gfield
