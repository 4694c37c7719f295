#pragma once
// numpy arrays (or anything numpy.asarray takes, e.g. nested lists) in, glint's plain types out,
// checked: a wrong dtype or shape, an index out of range or a NaN is a glint::Error whose one line
// names the argument, as glint's other errors name the file. Only these conversions touch numpy's
// layout; everything after them is plain C++.
#include "accel/ray.h"
#include "core/math.h"

#include <pybind11/numpy.h>

#include <cstdint>
#include <string_view>
#include <vector>

namespace glint::python {

// A float32 or float64 array of shape (N, 3) of finite numbers -> N points (float64 rounded to float).
std::vector<vec3> points_from_array(const pybind11::object& value, std::string_view what);

// An integer array of shape (M, 3) of vertex numbers in [0, vertex_count) -> 3M indices.
std::vector<uint32_t> indices_from_array(const pybind11::object& value, std::size_t vertex_count,
                                         std::string_view what);

// Rays from origins and directions (N, 3) as points_from_array, directions not zero, and t_min and
// t_max each a number or an array of N numbers (not NaN; t_max may be infinite).
std::vector<accel::Ray> rays_from_arrays(const pybind11::object& origins, const pybind11::object& directions,
                                         const pybind11::object& t_min, const pybind11::object& t_max,
                                         std::string_view what);

}  // namespace glint::python
