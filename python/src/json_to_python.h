#pragma once

// The library's JSON summaries (the CLI's --json output) as Python objects: objects become
// dicts, arrays lists, numbers int or float, so Python and `ridefit ... --json` report the same.

#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>

namespace ridefit::python {

pybind11::object to_python(const nlohmann::json& value);

}  // namespace ridefit::python
