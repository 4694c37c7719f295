#include "python/numpy_input.h"

#include "core/error.h"

#include <cmath>
#include <string>

namespace py = pybind11;

namespace glint::python {
namespace {

// "float64 array of shape (4, 3)", for messages.
std::string describe(const py::array& array) {
  std::string shape;
  for (py::ssize_t axis = 0; axis < array.ndim(); ++axis)
    shape += (axis == 0 ? "" : ", ") + std::to_string(array.shape(axis));
  if (array.ndim() == 1) shape += ",";
  return fmt::format("{} array of shape ({})", std::string(py::str(array.dtype())), shape);
}

bool has_shape_n3(const py::array& array) { return array.ndim() == 2 && array.shape(1) == 3; }

// numpy.asarray(value); glint::Error when numpy cannot make an array of it.
py::array as_array(const py::object& value, std::string_view what) {
  py::array array = py::array::ensure(value);
  if (!array) {
    PyErr_Clear();
    fail("{}: expected an array, got {}", what, std::string(py::str(py::type::of(value).attr("__name__"))));
  }
  return array;
}

// Per-ray parameter: a number for every ray, or one number per ray.
std::vector<float> per_ray_values(const py::object& value, std::size_t count, std::string_view what,
                                  std::string_view name) {
  const auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!array || !(array.ndim() == 0 || (array.ndim() == 1 && static_cast<std::size_t>(array.shape(0)) == count)))
    fail("{}: {} must be a number or an array of {} numbers (one per ray)", what, name, count);
  std::vector<float> values(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double v = array.ndim() == 0 ? *array.data() : array.data()[i];
    if (std::isnan(v)) fail("{}: {} of ray {} is NaN", what, name, i);
    values[i] = static_cast<float>(v);
  }
  return values;
}

}  // namespace

std::vector<vec3> points_from_array(const py::object& value, std::string_view what) {
  const py::array array = as_array(value, what);
  const char kind = array.dtype().kind();
  if (kind != 'f' || (array.itemsize() != 4 && array.itemsize() != 8) || !has_shape_n3(array))
    fail("{}: expected a float32 or float64 array of shape (N, 3), got a {}", what, describe(array));
  const auto floats = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(array);
  const auto rows = static_cast<std::size_t>(floats.shape(0));
  std::vector<vec3> points(rows);
  const float* data = floats.data();
  for (std::size_t i = 0; i < rows; ++i) {
    points[i] = vec3(data[3 * i], data[3 * i + 1], data[3 * i + 2]);
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y) || !std::isfinite(points[i].z))
      fail("{}: row {} is not finite ({}, {}, {})", what, i, points[i].x, points[i].y, points[i].z);
  }
  return points;
}

std::vector<uint32_t> indices_from_array(const py::object& value, std::size_t vertex_count, std::string_view what) {
  const py::array array = as_array(value, what);
  const char kind = array.dtype().kind();
  if ((kind != 'i' && kind != 'u') || !has_shape_n3(array))
    fail("{}: expected an integer array of shape (M, 3), got a {}", what, describe(array));
  // int64 holds every uint32 and int32; uint64 values past its range wrap negative and are refused below.
  const auto ints = py::array_t<int64_t, py::array::c_style | py::array::forcecast>::ensure(array);
  const auto count = static_cast<std::size_t>(ints.size());
  std::vector<uint32_t> indices(count);
  const int64_t* data = ints.data();
  for (std::size_t i = 0; i < count; ++i) {
    if (data[i] < 0 || static_cast<uint64_t>(data[i]) >= vertex_count)
      fail("{}: triangle {} uses vertex {}, but there are {} vertices", what, i / 3, data[i], vertex_count);
    indices[i] = static_cast<uint32_t>(data[i]);
  }
  return indices;
}

std::vector<accel::Ray> rays_from_arrays(const py::object& origins, const py::object& directions,
                                         const py::object& t_min, const py::object& t_max, std::string_view what) {
  const std::vector<vec3> from = points_from_array(origins, fmt::format("{}: origins", what));
  const std::vector<vec3> along = points_from_array(directions, fmt::format("{}: directions", what));
  if (from.size() != along.size())
    fail("{}: {} origins but {} directions (one of each per ray)", what, from.size(), along.size());
  const std::vector<float> near = per_ray_values(t_min, from.size(), what, "t_min");
  const std::vector<float> far = per_ray_values(t_max, from.size(), what, "t_max");
  std::vector<accel::Ray> rays(from.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    if (along[i] == vec3(0.0f)) fail("{}: direction {} is zero", what, i);
    rays[i] = accel::Ray{from[i], near[i], along[i], far[i]};
  }
  return rays;
}

}  // namespace glint::python
