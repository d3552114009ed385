// Models: load_model (a YAML file), model_from_dict (the same keys and checks), modes.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bindings.h"
#include "json_to_python.h"
#include "model_handle.h"
#include "ridefit/common/errors.h"
#include "ridefit/model/quarter_car_parameter_table.h"
#include "ridefit/simulate/half_car_modes.h"
#include "ridefit/simulate/modes_json.h"
#include "ridefit/simulate/quarter_car_modes.h"

namespace ridefit::python {

namespace py = pybind11;

namespace {

// `ridefit modes MODEL [--state S] --json`: every state's model is read and solved first.
nlohmann::json modes_json(const ModelHandle& model, const std::string& state) {
  if (!model.is_quarter_car()) {
    const io::HalfCarFile& file = model.half_car();
    return simulate::modes_json(
        model.name(),
        simulate::half_car_modes_by_state(file.topology, file.parameters, state, model.name()));
  }
  model.quarter_car("modes");
  if (!state.empty() && state != "slip" && state != "stick") {
    throw InputError("state: '" + state + "'; expected '' (both), 'slip' or 'stick'");
  }
  std::vector<simulate::StateModes> all;
  for (const std::string s : {"slip", "stick"}) {
    if (!state.empty() && s != state) continue;
    all.push_back(
        {s, simulate::quarter_car_modes(model.quarter_car_in_state(s, "--state").make_model())});
  }
  return simulate::modes_json(model.name(), all);
}

}  // namespace

void bind_model(py::module_& m) {
  py::class_<ModelHandle>(m, "Model",
                          "A quarter-car or half-car model read from a YAML file or a dict "
                          "(load_model, model_from_dict).")
      .def_property_readonly("kind", &ModelHandle::kind, "'quarter_car' or 'half_car'")
      .def_property_readonly("name", &ModelHandle::name,
                             "The file the model came from, or the dict's name")
      .def_property_readonly(
          "damper_state",
          [](const ModelHandle& model) {
            return std::string(model::to_string(model.quarter_car("damper_state").damper_state));
          },
          "The quarter car's topology: 'slip', 'stick' or 'stick_slip'")
      .def_property_readonly(
          "parameters",
          [](const ModelHandle& model) {
            const auto& p = model.quarter_car("parameters").parameters;
            py::dict values;
            for (std::size_t i = 0; i < model::kQuarterCarParameters.size(); ++i) {
              values[py::str(model::kQuarterCarParameters[i].key_string())] =
                  model::quarter_car_parameter(p, i);
            }
            return values;
          },
          "The quarter car's parameters by model-file key, in SI units (every row of the "
          "parameter table; an optional effect that is off holds its neutral value)")
      .def("__repr__", [](const ModelHandle& model) {
        return "<ridefit.Model " + model.kind() + " from " + model.name() + ">";
      });

  m.def("load_model", &ModelHandle::from_file, py::arg("path"), py::arg("overrides") = py::dict(),
        py::arg("damper_state") = "",
        R"(Reads a model file (YAML; `model: quarter_car` or `model: half_car`).

overrides: {key: value} replacing keys before the file is checked (the CLI's --set; dotted keys
such as 'front.damping_Ns_per_m' for the half car). damper_state: '', 'slip', 'stick' or
'stick_slip' (the CLI's --damper-state; quarter car). Raises InputError with the CLI's message
for unknown keys, missing keys and out-of-range values.)");
  m.def("model_from_dict", &ModelHandle::from_dict, py::arg("mapping"), py::arg("name") = "<dict>",
        py::arg("overrides") = py::dict(), py::arg("damper_state") = "",
        R"(A model from a dict with the keys of a model file, checked by the same rules.

Messages name `name` where a file's would name the file.)");
  m.def(
      "modes",
      [](const ModelHandle& model, const std::string& state) {
        return to_python(modes_json(model, state));
      },
      py::arg("model"), py::arg("state") = "",
      R"(Eigenfrequencies and damping ratios of the linear slip and stick quarter car.

state: '' (both), 'slip' or 'stick'. Returns the structure of `ridefit modes --json`:
{'model': name, 'states': {state: {'modes': [{'mode', 'natural_frequency_Hz',
'damped_frequency_Hz', 'damping_ratio', 'energy_share'}], 'first_order': [...]}}}.)");
}

}  // namespace ridefit::python
