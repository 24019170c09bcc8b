#include "runtime/work_counters.hpp"

#include "runtime/method.hpp"

namespace gfield {

void WorkCounters::clear() {
  if (!buffer_) {
    buffer_.make();
    glNamedBufferStorage(buffer_.id(), GLsizeiptr(gpu::WORK_COUNT * sizeof(std::uint32_t)), nullptr,
                         GL_DYNAMIC_STORAGE_BIT);
  }
  const std::uint32_t zero = 0;
  glClearNamedBufferData(buffer_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BUFFER_WORK, buffer_.id());
}

std::array<std::uint64_t, gpu::WORK_COUNT> WorkCounters::read() const {
  std::array<std::uint32_t, gpu::WORK_COUNT> raw{};
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(buffer_.id(), 0, GLsizeiptr(sizeof(raw)), raw.data());
  std::array<std::uint64_t, gpu::WORK_COUNT> counts{};
  for (int k = 0; k < gpu::WORK_COUNT; ++k)
    counts[size_t(k)] = raw[size_t(k)];
  return counts;
}

const char* work_count_name(int kind) {
  static const char* const names[gpu::WORK_COUNT] = {
      "field lookups",  "field texel fetches", "image texel fetches", "Newton steps",
      "BVH traversals", "BVH nodes",           "BVH triangles",       "counted rays"};
  return kind >= 0 && kind < gpu::WORK_COUNT ? names[kind] : "?";
}

void add_work_counts(FrameStats& stats, const std::array<std::uint64_t, gpu::WORK_COUNT>& counts) {
  for (int k = 0; k < gpu::WORK_COUNT; ++k)
    stats.add_count(work_count_name(k), double(counts[size_t(k)]));
}

}  // namespace gfield
