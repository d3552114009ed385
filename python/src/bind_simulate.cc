// simulate: a quarter car or half car over a road, every channel as a NumPy array under its CSV
// name (ridefit simulate -o), and the summary of `ridefit simulate --json` (solver statistics).
#include <pybind11/stl.h>

#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.h"
#include "json_to_python.h"
#include "model_handle.h"
#include "numpy_arrays.h"
#include "ridefit/common/errors.h"
#include "ridefit/simulate/half_car_simulation.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "ridefit/study/damper_command_note.h"
#include "ridefit/study/half_car_metrics.h"
#include "ridefit/study/response_table.h"
#include "ridefit/study/simulation_summary.h"
#include "road_handle.h"

namespace ridefit::python {

namespace py = pybind11;

namespace {

struct SimulateArguments {
  double output_rate_Hz = 1000.0;
  double duration_s = 0.0;
  std::string method = "esdirk";
  double rtol = 1e-5;
  double step_s = 1e-4;
  std::optional<double> rear_delay_s;
};

// The CLI's --method, --rtol and --step.
simulate::IntegratorOptions integrator_of(const SimulateArguments& a) {
  if (a.method != "esdirk" && a.method != "cvode" && a.method != "rk4") {
    throw InputError(fmt::format("method: '{}'; expected esdirk, cvode or rk4", a.method));
  }
  if (!(a.rtol > 0.0 && a.rtol <= 0.1)) {
    throw InputError(fmt::format("rtol: {} is not in (0, 0.1]", a.rtol));
  }
  if (!(a.step_s > 0.0) || !std::isfinite(a.step_s)) {
    throw InputError(fmt::format("step_s: {} is not a finite number > 0 s", a.step_s));
  }
  simulate::IntegratorOptions options;
  options.method = a.method == "rk4"     ? simulate::Method::kArkodeRk4
                   : a.method == "cvode" ? simulate::Method::kCvodeBdf
                                         : simulate::Method::kEsdirk;
  options.relative_tolerance = a.rtol;
  options.fixed_step_s = a.step_s;
  return options;
}

template <typename Options>
Options options_of(const SimulateArguments& a, const road::RoadInput& road) {
  try {
    simulate::check_output_rate(a.output_rate_Hz,
                                a.duration_s > 0.0 ? a.duration_s : road.duration_s());
  } catch (const InputError& e) {
    throw InputError(fmt::format("output_rate_Hz {}", e.what()));
  }
  Options options;
  options.output_rate_Hz = a.output_rate_Hz;
  options.duration_s = a.duration_s;
  options.integrator = integrator_of(a);
  return options;
}

// Runs without the GIL (Python threads go on meanwhile); the response and its wall time.
template <typename Car, typename Options>
auto timed_simulation(const Car& car, const road::RoadInput& road, const Options& options) {
  py::gil_scoped_release unlocked;
  const auto start = std::chrono::steady_clock::now();
  auto response = simulate::simulate(car, road, options);
  const double elapsed_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return std::make_pair(std::move(response), elapsed_s);
}

// (channels, units, summary, notes): the Python side wraps them in a SimulationResult.
using SimulationTuple = std::tuple<py::dict, py::dict, py::object, std::vector<std::string>>;

void add_channel(py::dict& channels, py::dict& units, const char* name, const char* unit,
                 std::vector<double>&& values) {
  channels[name] = to_numpy(std::move(values));
  units[name] = unit;
}

SimulationTuple simulate_quarter_car(const ModelHandle& model, const RoadHandle& road,
                                     const SimulateArguments& a) {
  if (a.rear_delay_s) {
    throw InputError("rear_delay_s: a quarter car has one wheel; the argument is for half cars");
  }
  const model::QuarterCar car =
      model.quarter_car("simulate").make_model().with_command_from_road(road.road->has_command());
  std::vector<std::string> notes;
  if (auto note = study::damper_command_note(car, *road.road, model.name(), road.name)) {
    notes.push_back(std::move(*note));
  }
  const auto options = options_of<simulate::SimulationOptions>(a, *road.road);
  auto [response, wall_time_s] = timed_simulation(car, *road.road, options);
  const study::SimulationRun run{model.name(), road.name, "", a.output_rate_Hz, wall_time_s};
  py::object summary = to_python(study::summary_json(run, car, response));
  // The channels of study::response_table, moved (not copied) into the arrays.
  py::dict channels;
  py::dict units;
  add_channel(channels, units, "time", "s", std::move(response.time_s));
  add_channel(channels, units, "road", "m", std::move(response.road_m));
  add_channel(channels, units, "body_acc", "m/s^2", std::move(response.body_acc_m_per_s2));
  add_channel(channels, units, "wheel_acc", "m/s^2", std::move(response.wheel_acc_m_per_s2));
  add_channel(channels, units, "travel", "m", std::move(response.travel_m));
  add_channel(channels, units, "tyre_force", "N", std::move(response.tyre_force_N));
  add_channel(channels, units, "damper_force", "N", std::move(response.damper_force_N));
  add_channel(channels, units, "friction_force", "N", std::move(response.friction_force_N));
  add_channel(channels, units, "top_mount_deflection", "m",
              std::move(response.top_mount_deflection_m));
  add_channel(channels, units, "stuck", "1", std::move(response.stuck));
  if (!response.damper_command.empty()) {
    const std::string unit = road.road->command_unit();
    channels["damper_command"] = to_numpy(std::move(response.damper_command));
    units["damper_command"] = unit;
  }
  return {channels, units, summary, notes};
}

SimulationTuple simulate_half_car(const ModelHandle& model, const RoadHandle& road,
                                  const SimulateArguments& a) {
  const model::HalfCar car = model.half_car().make_model();
  auto options = options_of<simulate::HalfCarSimulationOptions>(a, *road.road);
  if (a.rear_delay_s) options.rear_delay_s = *a.rear_delay_s;
  options.rear_delay_name = "rear_delay_s";
  const auto [response, wall_time_s] = timed_simulation(car, *road.road, options);
  // The ISO 2631-1 weightings need 500 Hz (Wk); a slower run reports what it can.
  const auto metrics =
      a.output_rate_Hz >= 500.0
          ? std::optional(study::half_car_metrics(response, model.half_car().parameters))
          : std::nullopt;
  const study::SimulationRun run{model.name(), road.name, "", a.output_rate_Hz, wall_time_s};
  py::object summary = to_python(study::summary_json(run, response, metrics));
  io::CsvTable table = study::response_table(response);
  py::dict channels;
  py::dict units;
  for (const auto& column : table.columns()) {
    std::vector<double> values = column.values;
    channels[py::str(column.name)] = to_numpy(std::move(values));
    units[py::str(column.name)] = column.unit;
  }
  return {channels, units, summary, {}};
}

}  // namespace

void bind_simulate(py::module_& m) {
  m.def(
      "_simulate",
      [](const ModelHandle& model, const RoadHandle& road, double output_rate_Hz, double duration_s,
         const std::string& method, double rtol, double step_s,
         std::optional<double> rear_delay_s) {
        const SimulateArguments a{output_rate_Hz, duration_s, method, rtol, step_s, rear_delay_s};
        if (!(duration_s >= 0.0) || !std::isfinite(duration_s)) {
          throw InputError(fmt::format("duration_s: {} is not a finite number >= 0 s", duration_s));
        }
        // The CLI's --rear-delay range.
        if (rear_delay_s && !(*rear_delay_s >= 0.0 && *rear_delay_s <= 100.0)) {
          throw InputError(fmt::format("rear_delay_s: {} is not in [0, 100] s", *rear_delay_s));
        }
        return model.is_quarter_car() ? simulate_quarter_car(model, road, a)
                                      : simulate_half_car(model, road, a);
      },
      py::arg("model"), py::arg("road"), py::arg("output_rate_Hz"), py::arg("duration_s"),
      py::arg("method"), py::arg("rtol"), py::arg("step_s"), py::arg("rear_delay_s"),
      "(channels, units, summary, notes) of a run; ridefit.simulate wraps it");
}

}  // namespace ridefit::python
