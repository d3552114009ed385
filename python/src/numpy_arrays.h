#pragma once

// NumPy arrays to and from the library's std::vector<double> and std::span<const double>.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <span>
#include <string>
#include <vector>

namespace ridefit::python {

// A float64 array that owns `values` (moved into a capsule): no copy of the samples.
pybind11::array_t<double> to_numpy(std::vector<double>&& values);

// A contiguous float64 array as a read-only view: `array` must be the result of
// pybind11::array_t<double, c_style | forcecast> (copied only when the caller's array is not
// already contiguous float64). InputError naming `what` when it is not one-dimensional.
std::span<const double> as_span(
    const pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>& array,
    const std::string& what);

using InputArray = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;

}  // namespace ridefit::python
