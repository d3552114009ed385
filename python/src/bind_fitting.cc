// Fits: fit_hysteresis (strut rig records, from arrays or CSV files) and fit_psd (a vehicle
// measurement's acceleration spectra), as `ridefit fit hysteresis|psd --json` runs them.
#include <pybind11/stl.h>

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.h"
#include "json_to_python.h"
#include "model_handle.h"
#include "numpy_arrays.h"
#include "ridefit/common/errors.h"
#include "ridefit/fitting/fit_adequacy.h"
#include "ridefit/fitting/fit_convergence.h"
#include "ridefit/fitting/hysteresis_fit.h"
#include "ridefit/fitting/hysteresis_fit_report.h"
#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/fitting/psd_fit.h"
#include "ridefit/fitting/psd_fit_report.h"
#include "ridefit/fitting/quantised_displacement.h"
#include "ridefit/fitting/robust_loss.h"
#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/fitting/strut_start.h"
#include "ridefit/io/model_values_file.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/model/quarter_car_parameter_table.h"
#include "ridefit/signal/signal_presence.h"

namespace ridefit::python {

namespace py = pybind11;

namespace {

std::vector<double> vector_of(const py::dict& record, const char* key, const std::string& source) {
  if (!record.contains(key)) {
    throw InputError(fmt::format("{}: no '{}' (a record holds time_s, displacement_m and force_N)",
                                 source, key));
  }
  const InputArray array = record[key].cast<InputArray>();
  const auto values = as_span(array, source + " " + key);
  return {values.begin(), values.end()};
}

// A rig record from arrays, checked as load_hysteresis_record checks a CSV: at least 20 samples
// of equal length, strictly increasing time, a displacement and a force that are not constant.
fitting::HysteresisRecord record_from_dict(const py::dict& record, std::size_t index) {
  fitting::HysteresisRecord r;
  r.source = record.contains("source") ? py::str(record["source"]).cast<std::string>()
                                       : fmt::format("record[{}]", index);
  r.time_s = vector_of(record, "time_s", r.source);
  r.displacement_m = vector_of(record, "displacement_m", r.source);
  r.force_N = vector_of(record, "force_N", r.source);
  if (record.contains("command")) {
    r.command = vector_of(record, "command", r.source);
    r.command_unit = record.contains("command_unit")
                         ? py::str(record["command_unit"]).cast<std::string>()
                         : std::string();
    if (r.command_unit != "A" && r.command_unit != "V") {
      throw InputError(fmt::format("{}: command_unit '{}'; a damper command is in A or V", r.source,
                                   r.command_unit));
    }
  }
  const std::size_t n = r.time_s.size();
  if (r.displacement_m.size() != n || r.force_N.size() != n ||
      (!r.command.empty() && r.command.size() != n)) {
    throw InputError(
        fmt::format("{}: the arrays differ in length ({} times, {} displacements, "
                    "{} forces)",
                    r.source, n, r.displacement_m.size(), r.force_N.size()));
  }
  if (n < 20) {
    throw InputError(
        fmt::format("{}: {} samples; a hysteresis fit needs at least 20", r.source, n));
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(r.time_s[i]) || (i > 0 && !(r.time_s[i] > r.time_s[i - 1]))) {
      throw InputError(
          fmt::format("{}: time_s[{}] = {} does not increase strictly", r.source, i, r.time_s[i]));
    }
  }
  for (const auto& [values, name] :
       {std::pair{&r.displacement_m, "displacement_m"}, std::pair{&r.force_N, "force_N"},
        std::pair{&r.command, "command"}}) {
    for (std::size_t i = 0; i < values->size(); ++i) {
      if (!std::isfinite((*values)[i])) {
        throw InputError(fmt::format("{}: {}[{}] is {}; every value must be finite", r.source, name,
                                     i, (*values)[i]));
      }
    }
  }
  signal::require_signal(r.displacement_m, r.source, "displacement", "m");
  signal::require_signal(r.force_N, r.source, "force", "N");
  fitting::examine_quantised_displacement(r);  // as the CSV loaders do
  return r;
}

// The records of the list (a CSV path gives a record per test, as the command reads it) and the
// files they came from. Per-file values with a file of several tests are refused as the command
// refuses them.
std::vector<fitting::HysteresisRecord> records_of(const py::list& records,
                                                  const std::vector<std::string>& per_file,
                                                  std::vector<std::filesystem::path>& files) {
  std::vector<fitting::HysteresisRecord> result;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const py::handle item = records[i];
    if (py::isinstance<py::str>(item)) {
      const std::string path = item.cast<std::string>();
      for (auto& test : fitting::load_rig_files(
               {path},
               per_file.empty() ? "" : fmt::format("per_file {}", fmt::join(per_file, ",")))) {
        result.push_back(std::move(test));
      }
      files.emplace_back(path);
    } else if (py::isinstance<py::dict>(item)) {
      result.push_back(record_from_dict(item.cast<py::dict>(), i));
      if (std::filesystem::exists(result.back().source)) files.emplace_back(result.back().source);
    } else {
      throw InputError(fmt::format(
          "records[{}]: a CSV path or a dict of arrays (time_s, displacement_m, force_N) expected",
          i));
    }
  }
  if (result.empty()) throw InputError("records: give at least one rig record");
  return result;
}

py::dict record_to_python(fitting::HysteresisRecord&& r) {
  py::dict out;
  out["source"] = r.source;
  out["time_s"] = to_numpy(std::move(r.time_s));
  out["displacement_m"] = to_numpy(std::move(r.displacement_m));
  out["force_N"] = to_numpy(std::move(r.force_N));
  if (!r.command.empty()) {
    out["command"] = to_numpy(std::move(r.command));
    out["command_unit"] = r.command_unit;
  }
  return out;
}

struct HysteresisArguments {
  std::vector<std::string> free;
  std::vector<std::string> per_file;
  std::map<std::string, std::pair<double, double>> bounds;
  std::map<std::string, double> starts;
  std::string loss;
  double loss_scale_N;
  double rtol;
  std::string interpolation;
  int max_iterations;
  std::vector<double> compression_mm;
  double max_nrmse_percent;
  std::string output;  // the fitted model (YAML), "" for none: the CLI's -o
  bool keep;           // write it even when it does not explain the data
  std::string record_weights;
};

// The CLI's flag checks (fit_hysteresis_command.cc), in the arguments' names.
void check_arguments(const HysteresisArguments& a, std::size_t record_count) {
  for (const auto& [name, bound] : a.bounds) {
    fitting::strut_parameter_index(name);
    const bool fitted = std::ranges::count(a.free, name) + std::ranges::count(a.per_file, name) > 0;
    if (fitted) continue;
    throw InputError(fmt::format(
        "bounds {}=({}, {}): {} is not fitted (free: {}), so the bound would be ignored; add it "
        "to free or leave the bound out",
        name, bound.first, bound.second, name, fmt::join(a.free, ",")));
  }
  if (!a.compression_mm.empty() &&
      (a.compression_mm.size() != record_count ||
       std::ranges::count(a.per_file, model::quarter_car_rows::coulomb_force_N.key) == 0)) {
    throw InputError(
        fmt::format("compression_mm: give one spring compression per record ({} records) and fit "
                    "coulomb_force_N per file (per_file=['coulomb_force_N'])",
                    record_count));
  }
  if (a.interpolation != "spline" && a.interpolation != "linear") {
    throw InputError(
        fmt::format("interpolation: '{}'; expected spline or linear", a.interpolation));
  }
  if (!(a.rtol > 0.0 && a.rtol <= 0.1)) {
    throw InputError(fmt::format("rtol: {} is not in (0, 0.1]", a.rtol));
  }
}

py::object fit_hysteresis(const py::list& record_list, const ModelHandle& model,
                          const HysteresisArguments& a) {
  std::vector<std::filesystem::path> files;
  std::vector<fitting::HysteresisRecord> records = records_of(record_list, a.per_file, files);
  const io::QuarterCarFile& file = model.quarter_car("fit_hysteresis");
  check_arguments(a, records.size());
  // With per-file parameters and several records, one model per record (as the CLI's -o).
  std::vector<std::filesystem::path> model_outputs;
  if (!a.output.empty()) {
    if (records.size() == 1 || a.per_file.empty()) {
      model_outputs.emplace_back(a.output);
    } else {
      for (const auto& r : records)
        model_outputs.push_back(io::output_for_input(a.output, r.source));
    }
  }
  if (const auto repeated = io::first_repeated_file(files)) {
    throw InputError(fmt::format(
        "{} is given twice; a repeated record would count twice in the fit", repeated->string()));
  }
  std::vector<std::filesystem::path> inputs = files;
  inputs.push_back(model.path());
  io::RunOutputs outputs(inputs);
  for (const auto& path : model_outputs) outputs.add_file(path, "output");
  fitting::HysteresisFitOptions options;
  options.free = a.free;
  options.per_file = a.per_file;
  options.bounds = a.bounds;
  options.loss = fitting::parse_robust_loss(a.loss);
  options.loss_scale_N = a.loss_scale_N;
  options.record_weighting = fitting::parse_record_weighting(a.record_weights);
  options.solver.relative_tolerance = a.rtol;
  options.solver.interpolation = a.interpolation == "linear" ? simulate::RigInterpolation::kLinear
                                                             : simulate::RigInterpolation::kSpline;
  options.max_iterations = a.max_iterations;
  options.max_nrmse_percent = a.max_nrmse_percent;
  const model::StrutTestParameters<double> start = [&] {
    try {
      return fitting::with_strut_values(fitting::strut_on_rig(file.parameters), a.starts);
    } catch (const InputError& e) {
      throw InputError(fmt::format("starts {}", e.what()));
    }
  }();
  std::string chosen;
  fitting::HysteresisFitResult fit;
  {
    py::gil_scoped_release unlocked;
    fit = fitting::fit_hysteresis_from_file_and_records(records, start, options, &chosen);
  }
  fitting::require_convergence(fit.converged, fit.explains_data, "the fit", fit.iterations,
                               fit.termination,
                               "better start values (starts=) or fewer free parameters");
  std::vector<double> compression_m;
  for (double mm : a.compression_mm) compression_m.push_back(1e-3 * mm);
  const fitting::HysteresisFitReport report =
      fitting::report_hysteresis_fit(records, fit, chosen, compression_m);
  py::list written;
  if (fit.explains_data || a.keep) {
    for (std::size_t r = 0; r < model_outputs.size(); ++r) {
      io::write_model_with_values(
          model.path(),
          fitting::model_file_values(fit.fitted[r], fitting::written_parameters(a.free, a.starts)),
          model_outputs[r], "Fitted by ridefit.fit_hysteresis from " + model.name());
      written.append(model_outputs[r].string());
    }
  }
  py::dict summary = to_python(fitting::summary_json(fit, report));
  summary["written"] = written;
  py::list fitted;
  for (auto& force : fit.fitted_force_N) fitted.append(to_numpy(std::move(force)));
  summary["fitted_force_N"] = fitted;
  py::list measured;
  for (auto& record : records) measured.append(record_to_python(std::move(record)));
  summary["records"] = measured;
  return summary;
}

struct PsdArguments {
  std::vector<std::string> free;
  std::string excitation;
  std::pair<double, double> band_Hz;
  double segment_s;
  int starts;
  int max_iterations;
  std::string loss;
  double rtol;
  std::optional<double> body_noise_psd;
  std::optional<double> wheel_noise_psd;
  double max_nrmse_percent;
  std::string output;
  bool keep;
};

py::object fit_psd(const std::string& measurement_file, const ModelHandle& model,
                   const PsdArguments& a) {
  if (!(a.band_Hz.first < a.band_Hz.second)) {
    throw InputError("band_Hz: expected (LOW, HIGH) in Hz with LOW < HIGH, e.g. (0.5, 30)");
  }
  const io::QuarterCarFile& file = model.quarter_car("fit_psd");
  std::vector<std::filesystem::path> inputs = {measurement_file, model.path()};
  if (!a.excitation.empty()) inputs.emplace_back(a.excitation);
  io::RunOutputs outputs(inputs);
  outputs.add_file(a.output, "output");
  const fitting::PsdMeasurement measurement =
      fitting::load_psd_measurement(measurement_file, a.excitation);
  for (const auto& [noise, name] : {std::pair{a.body_noise_psd, "body_noise_psd"},
                                    std::pair{a.wheel_noise_psd, "wheel_noise_psd"}}) {
    if (noise && !(*noise >= 0.0 && std::isfinite(*noise))) {
      throw InputError(fmt::format("{}: {} is not a finite PSD level >= 0", name, *noise));
    }
  }
  fitting::PsdFitOptions options;
  options.free = a.free;
  options.band_low_Hz = a.band_Hz.first;
  options.band_high_Hz = a.band_Hz.second;
  options.segment_s = a.segment_s;
  options.starts = a.starts;
  options.max_iterations = a.max_iterations;
  options.loss = fitting::parse_robust_loss(a.loss);
  options.relative_tolerance = a.rtol;
  options.body_noise_psd = a.body_noise_psd;
  options.wheel_noise_psd = a.wheel_noise_psd;
  fitting::PsdFitResult fit;
  fitting::FitAdequacy adequacy;
  {
    py::gil_scoped_release unlocked;
    fit = fitting::fit_psd(measurement, file.make_model(), options);
    adequacy = fitting::assess_psd_fit(fit, file.parameters, options, a.max_nrmse_percent);
  }
  fitting::require_convergence(fit.converged, adequacy.explains_data, "the PSD fit", fit.iterations,
                               fit.termination, "starts=5 or fewer free parameters");
  py::list written;
  if (!a.output.empty() && (adequacy.explains_data || a.keep)) {
    std::vector<std::pair<std::string, double>> values;
    for (std::size_t i = 0; i < fit.names.size(); ++i)
      values.emplace_back(fit.names[i], fit.values[i]);
    io::write_model_with_values(
        model.path(), values, a.output,
        fmt::format("Fitted by ridefit.fit_psd from {} and {}", model.name(), measurement_file));
    written.append(a.output);
  }
  py::dict summary = to_python(fitting::summary_json(fit, adequacy));
  summary["written"] = written;
  py::dict spectra;
  spectra["frequency_Hz"] = to_numpy(std::move(fit.frequency_Hz));
  spectra["measured_body_psd"] = to_numpy(std::move(fit.measured_body_psd));
  spectra["fitted_body_psd"] = to_numpy(std::move(fit.fitted_body_psd));
  spectra["measured_wheel_psd"] = to_numpy(std::move(fit.measured_wheel_psd));
  spectra["fitted_wheel_psd"] = to_numpy(std::move(fit.fitted_wheel_psd));
  summary["spectra"] = spectra;
  return summary;
}

}  // namespace

void bind_fitting(py::module_& m) {
  m.def(
      "load_hysteresis_record",
      [](const std::string& path) {
        return record_to_python(fitting::load_hysteresis_record(path));
      },
      py::arg("path"),
      R"(A strut rig record (CSV: time, displacement, force[, current|voltage]) in SI units:
{'source', 'time_s', 'displacement_m', 'force_N'[, 'command', 'command_unit']}.)");
  m.def(
      "_fit_hysteresis",
      [](const py::list& records, const ModelHandle& model, std::vector<std::string> free,
         std::vector<std::string> per_file, std::map<std::string, std::pair<double, double>> bounds,
         std::map<std::string, double> starts, std::string loss, double loss_scale_N, double rtol,
         std::string interpolation, int max_iterations, std::vector<double> compression_mm,
         double max_nrmse_percent, std::string output, bool keep, std::string record_weights) {
        const HysteresisArguments a{std::move(free),
                                    std::move(per_file),
                                    std::move(bounds),
                                    std::move(starts),
                                    std::move(loss),
                                    loss_scale_N,
                                    rtol,
                                    std::move(interpolation),
                                    max_iterations,
                                    std::move(compression_mm),
                                    max_nrmse_percent,
                                    std::move(output),
                                    keep,
                                    std::move(record_weights)};
        return fit_hysteresis(records, model, a);
      },
      "ridefit.fit_hysteresis without its defaults");
  m.def(
      "_fit_psd",
      [](const std::string& measurement, const ModelHandle& model, std::vector<std::string> free,
         std::string excitation, std::pair<double, double> band_Hz, double segment_s, int starts,
         int max_iterations, std::string loss, double rtol, std::optional<double> body_noise_psd,
         std::optional<double> wheel_noise_psd, double max_nrmse_percent, std::string output,
         bool keep) {
        const PsdArguments a{
            std::move(free),   std::move(excitation), band_Hz, segment_s,      starts,
            max_iterations,    std::move(loss),       rtol,    body_noise_psd, wheel_noise_psd,
            max_nrmse_percent, std::move(output),     keep};
        return fit_psd(measurement, model, a);
      },
      "ridefit.fit_psd without its defaults");
}

}  // namespace ridefit::python
