#include "progress_callback.h"

namespace ridefit::python {

namespace py = pybind11;

std::function<void(const std::string&)> progress_callback(const py::object& callback) {
  if (callback.is_none()) return {};
  // A borrowed handle: copies of the std::function (made without the GIL) touch no refcount.
  const py::handle target = callback;
  return [target](const std::string& line) {
    py::gil_scoped_acquire gil;
    try {
      target(line);
    } catch (py::error_already_set& e) {
      e.discard_as_unraisable("ridefit progress callback");
    }
  };
}

}  // namespace ridefit::python
