#include "python/src/ray_batch.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace gfield::python {

namespace {

/// The largest direction coordinate: its square and the sums of three stay finite in float.
constexpr float kMaxDirection = 1e18f;

std::string row(const char* name, size_t i) {
  return std::string(name) + "[" + std::to_string(i) + "]";
}

std::string vec_text(const float* v) {
  return "(" + std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " + std::to_string(v[2]) +
         ")";
}

/// Raises ValueError naming the first ray that no lookup or cast may take.
void check_rays(const RayBatch& b) {
  for (size_t i = 0; i < b.count; ++i) {
    const float* o = b.origin_values + 3 * i;
    const float* d = b.direction_values + 3 * i;
    if (!std::isfinite(o[0]) || !std::isfinite(o[1]) || !std::isfinite(o[2]))
      throw py::value_error(row("origins", i) + ": " + vec_text(o) + " is not finite");
    const float longest = std::max({std::fabs(d[0]), std::fabs(d[1]), std::fabs(d[2])});
    if (!(longest <= kMaxDirection) || longest == 0.0f)
      throw py::value_error(row("directions", i) + ": " + vec_text(d) +
                            (longest == 0.0f ? " is zero" : " is not finite or beyond 1e18"));
  }
  for (size_t i = 0; i < (b.one_t_min ? 1 : b.count); ++i) {
    const float t = b.t_min_values[i];
    if (!(t >= 0.0f))
      throw py::value_error((b.one_t_min ? std::string("t_min") : row("t_min", i)) + ": " +
                            std::to_string(t) + (t < 0.0f ? " is negative" : " is not a number") +
                            " (rays start at t >= 0)");
  }
}

}  // namespace

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
  if (t_min.is_none() || py::isinstance<py::str>(t_min) || py::isinstance<py::bytes>(t_min))
    throw py::type_error("t_min: expected a number or an array of numbers, not " +
                         std::string(py::str(py::type::of(t_min).attr("__name__"))));
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
  check_rays(batch);
  return batch;
}

}  // namespace gfield::python
