#include "python/src/ray_batch.hpp"

namespace gfield::python {

RayBatch ray_batch(const py::object& origins, const py::object& directions,
                   const py::object& t_min) {
  RayBatch batch;
  batch.origins = float_rows(origins, "origins", 3);
  batch.directions = float_rows(directions, "directions", 3);
  batch.count = size_t(batch.origins.shape(0));
  if (size_t(batch.directions.shape(0)) != batch.count) {
    throw py::value_error("directions: " + std::to_string(batch.directions.shape(0)) +
                          " rows for " + std::to_string(batch.count) + " origins");
  }
  auto start = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(t_min);
  const bool one = start && start.ndim() == 0;
  const bool each = start && start.ndim() == 1 && size_t(start.shape(0)) == batch.count;
  if (!one && !each) {
    throw py::value_error("t_min: expected a number or an array of shape (" +
                          std::to_string(batch.count) + ",)");
  }
  batch.t_min = start;
  batch.origin_values = batch.origins.data();
  batch.direction_values = batch.directions.data();
  batch.t_min_values = batch.t_min.data();
  batch.one_t_min = one;
  return batch;
}

}  // namespace gfield::python
