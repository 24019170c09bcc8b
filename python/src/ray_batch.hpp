#pragma once
// Batches of rays from numpy arrays, answered on every core with the GIL released: the inputs of
// GeometryField.lookup and Mesh.intersect and the arrays of their answers.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstddef>

#include <glm/glm.hpp>

#include "python/src/bindings.hpp"
#include "python/src/interruptible.hpp"

namespace gfield::python {

/// R rays: origins and directions (R, 3) float32 and t_min per ray (one value for all, or R).
/// The arrays are held; their values are read through the pointers, without the GIL.
struct RayBatch {
  py::array_t<float, py::array::c_style> origins;
  py::array_t<float, py::array::c_style> directions;
  py::array_t<float, py::array::c_style> t_min;
  size_t count = 0;
  const float* origin_values = nullptr;     ///< 3R
  const float* direction_values = nullptr;  ///< 3R
  const float* t_min_values = nullptr;      ///< 1 or R
  bool one_t_min = true;

  glm::vec3 origin(size_t i) const {
    return {origin_values[3 * i], origin_values[3 * i + 1], origin_values[3 * i + 2]};
  }
  glm::vec3 direction(size_t i) const {
    return {direction_values[3 * i], direction_values[3 * i + 1], direction_values[3 * i + 2]};
  }
  float start(size_t i) const { return t_min_values[one_t_min ? 0 : i]; }  ///< t_min of ray i
};

/// The batch of (origins, directions, t_min) as the Python functions take them: array-likes of
/// shape (R, 3), (R, 3), and a number or an array-like of shape (R,). Raises ValueError naming
/// the argument for another shape.
RayBatch ray_batch(const py::object& origins, const py::object& directions,
                   const py::object& t_min);

/// Calls `answer(i)` for i in [0, count) on TBB's threads with the GIL released, as an
/// interruptible job (python/src/interruptible.hpp): a Ctrl-C raises KeyboardInterrupt within
/// about 50 ms plus one block of rays. A template, so that `answer` is inlined into the loop over
/// each block: no call per ray that a C++ program looping over its rays would not make. Call
/// with the GIL held.
template <class Answer>
void for_each_ray(size_t count, const Answer& answer) {
  constexpr size_t kBlock = 4096;  // rays between two looks at the stop flag
  run_interruptible(
      [&](const JobControl& control) {
        tbb::parallel_for(
            tbb::blocked_range<size_t>(0, count, kBlock),
            [&](const tbb::blocked_range<size_t>& range) {
              if (stop_requested(&control)) {
                return;
              }
              for (size_t i = range.begin(); i != range.end(); ++i) {
                answer(i);
              }
            },
            tbb::simple_partitioner());
      },
      py::none());
}

/// A new array of `count` rows of `columns` values (columns 0: shape (count,)).
template <class T>
py::array_t<T> answer_array(size_t count, py::ssize_t columns = 0) {
  if (columns == 0) {
    return py::array_t<T>({py::ssize_t(count)});
  }
  return py::array_t<T>({py::ssize_t(count), columns});
}

}  // namespace gfield::python
