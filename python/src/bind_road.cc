// Roads: an excitation file or dict (every `type` of road/excitation_file.h), or measured arrays.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <fmt/core.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "bindings.h"
#include "dict_file.h"
#include "numpy_arrays.h"
#include "ridefit/common/errors.h"
#include "ridefit/road/excitation_file.h"
#include "ridefit/road/measured_road.h"
#include "ridefit/road/profile_road.h"
#include "road_handle.h"

namespace ridefit::python {

namespace py = pybind11;

namespace {

RoadHandle road_from_file(const std::filesystem::path& path) {
  return {std::shared_ptr<const road::RoadInput>(road::load_excitation(path)), path.string()};
}

// A relative `file:` is taken relative to the working directory (a dict has no directory of its
// own), as a path given to any Python function is.
RoadHandle road_from_dict(py::dict mapping, const std::string& name) {
  py::dict copy = mapping.attr("copy")();
  if (copy.contains("file") && py::isinstance<py::str>(copy["file"])) {
    const std::filesystem::path file = copy["file"].cast<std::string>();
    if (file.is_relative()) copy["file"] = std::filesystem::absolute(file).string();
  }
  const DictFile dict(copy, name);
  auto road = read_renamed(dict, [&] { return road::load_excitation(dict.path()); });
  return {std::shared_ptr<const road::RoadInput>(std::move(road)), name};
}

RoadHandle road_from_arrays(const InputArray& time_s, const InputArray& elevation_m,
                            const std::optional<InputArray>& command,
                            const std::string& command_unit) {
  const auto time = as_span(time_s, "time_s");
  const auto elevation = as_span(elevation_m, "elevation_m");
  if (command) {
    if (command_unit != "A" && command_unit != "V") {
      throw InputError("command_unit: '" + command_unit +
                       "'; a damper command is a current (A) or a voltage (V)");
    }
    return {std::make_shared<road::MeasuredRoad>(time, elevation, as_span(*command, "command"),
                                                 command_unit),
            "<arrays>"};
  }
  return {std::make_shared<road::MeasuredRoad>(time, elevation), "<arrays>"};
}

// A spatial profile h(x) driven at a speed, as `type: profile` drives a CSV.
RoadHandle road_from_profile(const InputArray& distance_m, const InputArray& elevation_m,
                             double speed_m_per_s, double offset_m) {
  if (!(speed_m_per_s > 0.0) || !std::isfinite(speed_m_per_s)) {
    throw InputError(fmt::format("speed_m_per_s: {} is not a finite speed > 0", speed_m_per_s));
  }
  if (!std::isfinite(offset_m)) throw InputError("offset_m: not a finite distance");
  road::ProfileRoadParameters parameters;
  parameters.speed_m_per_s = speed_m_per_s;
  parameters.offset_m = offset_m;
  return {std::make_shared<road::SpatialProfileRoad>(road::make_profile_road(
              as_span(distance_m, "distance_m"), as_span(elevation_m, "elevation_m"), parameters)),
          "<arrays>"};
}

}  // namespace

void bind_road(py::module_& m) {
  py::class_<RoadHandle>(m, "Road",
                         "The road under a tyre over time: h(t) and dh/dt (load_excitation, "
                         "road_from_dict, measured_road).")
      .def_property_readonly(
          "duration_s", [](const RoadHandle& r) { return r.road->duration_s(); },
          "Length of the excitation [s]; simulations run to it by default")
      .def_property_readonly(
          "speed_m_per_s", [](const RoadHandle& r) { return r.road->speed_m_per_s(); },
          "Driving speed of a road driven over a profile, None for roads given over time")
      .def_property_readonly("name", [](const RoadHandle& r) { return r.name; })
      .def(
          "sample",
          [](const RoadHandle& r, const InputArray& time_s) {
            const auto times = as_span(time_s, "time_s");
            std::vector<double> elevation(times.size());
            std::vector<double> rate(times.size());
            for (std::size_t i = 0; i < times.size(); ++i) {
              const road::RoadSample s = r.road->at(times[i]);
              elevation[i] = s.elevation_m;
              rate[i] = s.rate_m_per_s;
            }
            py::dict out;
            out["elevation_m"] = to_numpy(std::move(elevation));
            out["rate_m_per_s"] = to_numpy(std::move(rate));
            return out;
          },
          py::arg("time_s"), "{'elevation_m': h(t), 'rate_m_per_s': dh/dt} at the given times")
      .def("__repr__", [](const RoadHandle& r) { return "<ridefit.Road from " + r.name + ">"; });

  m.def("load_excitation", &road_from_file, py::arg("path"),
        R"(A road from an excitation file (YAML with `type`: log_sweep, iso8608, power_law, cleat,
profile, measured, opencrg), exactly as `ridefit simulate MODEL EXCITATION` reads it.)");
  m.def("road_from_dict", &road_from_dict, py::arg("mapping"), py::arg("name") = "<dict>",
        R"(A road from a dict with the keys of an excitation file, checked by the same rules;
e.g. {'type': 'iso8608', 'class': 'B', 'speed_km_per_h': 50, 'duration_s': 20}.)");
  m.def("_profile_road", &road_from_profile, py::arg("distance_m"), py::arg("elevation_m"),
        py::arg("speed_m_per_s"), py::arg("offset_m"), "ridefit.profile_road without defaults");
  m.def("measured_road", &road_from_arrays, py::arg("time_s"), py::arg("elevation_m"),
        py::arg("command") = py::none(), py::arg("command_unit") = "",
        R"(A road elevation recorded over time (arrays in s and m), as `type: measured` reads a
CSV: at least 5 samples with strictly increasing time; non-uniform samples are resampled. An
optional damper command (A or V, command_unit) on the same time base.)");
}

}  // namespace ridefit::python
