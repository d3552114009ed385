// diagnose: which physical effect the model misses, for vehicle spectra or strut rig loops, with
// the JSON structure of `ridefit diagnose --json` as a dict (no output folder is written).
#include <pybind11/stl.h>

#include <fmt/core.h>

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.h"
#include "json_to_python.h"
#include "model_handle.h"
#include "progress_callback.h"
#include "ridefit/common/errors.h"
#include "ridefit/fitting/diagnose/diagnosis.h"
#include "ridefit/fitting/diagnose/diagnosis_records.h"
#include "ridefit/fitting/diagnose/effect.h"
#include "ridefit/fitting/diagnose/loop_diagnosis.h"
#include "ridefit/fitting/diagnose/loop_report.h"
#include "ridefit/fitting/diagnose/spectra_report.h"
#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/fitting/psd_fit.h"
#include "ridefit/fitting/record_kind.h"
#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::python {

namespace py = pybind11;
namespace dx = fitting::diagnose;

namespace {

struct DiagnoseArguments {
  std::vector<std::string> records;
  std::vector<std::string> excitations;
  std::vector<std::string> effects;  // empty: all
  std::vector<std::string> free;
  // The baseline's tolerances as given (a dict, or {} for "none"); none given: the data kind's
  // data sheet when `datasheet`, else its default (as the CLI's --tolerances: spectra hold the
  // values, rig loops free the strut's sheet values).
  std::optional<std::map<std::string, double>> tolerances;
  bool datasheet;
  std::pair<double, double> band_Hz;
  double segment_s;
  double screening_rtol;
  double rtol;
  std::optional<double> body_noise_psd;
  std::optional<double> wheel_noise_psd;
  unsigned threads;
  std::function<void(const std::string&)> progress;
};

void check_effects(const std::vector<std::string>& ids) {
  for (const auto& id : ids) {
    try {
      dx::find_effect(id);
    } catch (const InputError& e) {
      throw InputError(fmt::format("effects: {}", e.what()));
    }
  }
}

nlohmann::json diagnose_loops(const ModelHandle& model, const DiagnoseArguments& a) {
  if (!a.excitations.empty()) {
    throw InputError(
        "excitations: strut rig records carry their own excitation (the displacement column); "
        "give none");
  }
  dx::LoopDiagnosisOptions options;
  options.effects = a.effects;
  for (const auto& name : a.free) {
    try {
      fitting::strut_parameter_index(name);
    } catch (const InputError& e) {
      throw InputError(fmt::format("free: {}", e.what()));
    }
  }
  options.baseline_free = a.free;
  if (a.tolerances) options.baseline_tolerances = *a.tolerances;  // else the strut's sheet
  options.selection.threads = a.threads;
  const io::QuarterCarFile& file = model.quarter_car("diagnose");
  std::vector<std::filesystem::path> files(a.records.begin(), a.records.end());
  const dx::LoopDiagnosisData data = dx::load_loop_diagnosis_data(files);
  dx::DiagnosisModel baseline;
  baseline.car = file.make_model();
  baseline.kind = dx::DataKind::kStrutLoops;
  baseline.strut = fitting::strut_on_rig(file.make_model());
  py::gil_scoped_release unlocked;
  return dx::loop_summary_json(dx::diagnose_loops(baseline, data, options, a.progress));
}

nlohmann::json diagnose_spectra(const ModelHandle& model, const DiagnoseArguments& a) {
  if (a.records.empty() || a.records.size() > 2) {
    throw InputError(
        "give one record (its first half is fitted, its second half judges) or two (the first "
        "is fitted, the second judges)");
  }
  if (a.excitations.size() > 1 && a.excitations.size() != a.records.size()) {
    throw InputError(fmt::format(
        "excitations: give one for all records or one per record ({} records, {} excitations)",
        a.records.size(), a.excitations.size()));
  }
  if (!(a.band_Hz.first > 0.0) || !(a.band_Hz.first < a.band_Hz.second)) {
    throw InputError("band_Hz: expected (LOW, HIGH) in Hz with 0 < LOW < HIGH, e.g. (0.5, 30)");
  }
  dx::DiagnosisOptions options;
  options.effects = a.effects;
  for (const auto& name : a.free) {
    if (!model::quarter_car_parameter_index(name)) {
      throw InputError(fmt::format("free: '{}' is not a quarter-car parameter", name));
    }
  }
  options.baseline_free = a.free;
  options.baseline_tolerances = a.tolerances  ? *a.tolerances
                                : a.datasheet ? dx::datasheet_tolerances()
                                              : std::map<std::string, double>{};
  options.fit.band_low_Hz = a.band_Hz.first;
  options.fit.band_high_Hz = a.band_Hz.second;
  options.fit.segment_s = a.segment_s;
  options.screening_relative_tolerance = a.screening_rtol;
  options.final_relative_tolerance = a.rtol;
  options.map.segment_s = a.segment_s;
  options.fit.body_noise_psd = a.body_noise_psd;
  options.fit.wheel_noise_psd = a.wheel_noise_psd;
  options.selection.threads = a.threads;
  const io::QuarterCarFile& file = model.quarter_car("diagnose");
  const dx::DiagnosisData data = dx::load_diagnosis_data(
      {a.records.begin(), a.records.end()}, {a.excitations.begin(), a.excitations.end()});
  // Each part holds two Welch segments or more, and the band ends below its Nyquist frequency.
  for (const auto* m : {&data.training, &data.held_out}) {
    const double length_s = m->time_s.back() - m->time_s.front();
    if (length_s < 2.0 * a.segment_s) {
      throw InputError(fmt::format(
          "{}: {:.3g} s of data for fitting or judging, fewer than two {:g} s segments; give a "
          "longer record, a second record, or a shorter segment_s",
          m->source, length_s, a.segment_s));
    }
    if (a.band_Hz.second >= 0.5 * m->sample_rate_Hz) {
      throw InputError(
          fmt::format("band_Hz: {:g} Hz is at or above the Nyquist frequency of {} ({:g} Hz)",
                      a.band_Hz.second, m->source, 0.5 * m->sample_rate_Hz));
    }
  }
  for (const auto* m : {&data.training, &data.held_out}) fitting::noise_floors(*m, options.fit);
  py::gil_scoped_release unlocked;
  return dx::spectra_summary_json(dx::diagnose({file.make_model()}, data, options, a.progress));
}

}  // namespace

void bind_diagnose(py::module_& m) {
  m.def(
      "_diagnose",
      [](const ModelHandle& model, std::vector<std::string> records,
         std::vector<std::string> excitations, std::vector<std::string> effects,
         std::vector<std::string> free, std::optional<std::map<std::string, double>> tolerances,
         bool datasheet, std::pair<double, double> band_Hz, double segment_s, double screening_rtol,
         double rtol, std::optional<double> body_noise_psd, std::optional<double> wheel_noise_psd,
         unsigned threads, const py::object& progress) {
        check_effects(effects);
        const DiagnoseArguments a{std::move(records),
                                  std::move(excitations),
                                  std::move(effects),
                                  std::move(free),
                                  std::move(tolerances),
                                  datasheet,
                                  band_Hz,
                                  segment_s,
                                  screening_rtol,
                                  rtol,
                                  body_noise_psd,
                                  wheel_noise_psd,
                                  threads,
                                  progress_callback(progress)};
        if (a.records.empty()) throw InputError("records: give one or two records");
        std::size_t rig = 0;
        for (const auto& file : a.records) rig += fitting::is_rig_record(file) ? 1 : 0;
        if (rig > 0 && rig == a.records.size()) return to_python(diagnose_loops(model, a));
        if (rig > 0) {
          throw InputError(
              "the records mix strut rig tests (time, displacement, force) with vehicle "
              "measurements (time, road or --excitation, body_acc and/or wheel_acc); diagnose one "
              "kind at a time");
        }
        return to_python(diagnose_spectra(model, a));
      },
      "ridefit.diagnose without its defaults");
}

}  // namespace ridefit::python
