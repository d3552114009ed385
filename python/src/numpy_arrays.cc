#include "numpy_arrays.h"

#include <fmt/core.h>

#include <utility>

#include "ridefit/common/errors.h"

namespace ridefit::python {

namespace py = pybind11;

py::array_t<double> to_numpy(std::vector<double>&& values) {
  auto* owner = new std::vector<double>(std::move(values));
  py::capsule free_when_done(owner, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return py::array_t<double>(static_cast<py::ssize_t>(owner->size()), owner->data(),
                             free_when_done);
}

std::span<const double> as_span(const InputArray& array, const std::string& what) {
  if (array.ndim() != 1) {
    throw InputError(
        fmt::format("{}: a one-dimensional array expected, got {} dimensions", what, array.ndim()));
  }
  return {array.data(), static_cast<std::size_t>(array.size())};
}

}  // namespace ridefit::python
