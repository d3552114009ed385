#pragma once

// A Python callable as the library's progress callback, safe to call from the library's worker
// threads while the GIL is released: each call takes the GIL, and an exception the callable
// raises is reported as unraisable (it cannot cross a worker thread) instead of ending the run.

#include <pybind11/pybind11.h>

#include <functional>
#include <string>

namespace ridefit::python {

// Empty for None. `callback` must outlive the returned function (the caller's argument does).
std::function<void(const std::string&)> progress_callback(const pybind11::object& callback);

}  // namespace ridefit::python
