// analyse: the metrics, ISO 2631-1 comfort values and averaged spectra of recordings, as
// `ridefit analyse --json` reports them (study/recording_analysis.h), with the spectra as arrays.
#include <pybind11/stl.h>

#include <fmt/core.h>

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.h"
#include "json_to_python.h"
#include "model_handle.h"
#include "numpy_arrays.h"
#include "ridefit/comfort/frequency_weighting.h"
#include "ridefit/comfort/tyre_load_metrics.h"
#include "ridefit/common/errors.h"
#include "ridefit/signal/detrend.h"
#include "ridefit/study/recording_analysis.h"
#include "ridefit/study/recording_analysis_json.h"

namespace ridefit::python {

namespace py = pybind11;

namespace {

struct AnalyseArguments {
  std::vector<std::string> files;
  std::vector<std::string> channels;
  std::string weighting;
  std::pair<double, double> band_Hz;
  double segment_s;
  double overlap;
  std::string detrend;
  int smooth_bins;
  double confidence;
  std::optional<double> static_tyre_load_N;
  const ModelHandle* model;  // null: none
  std::optional<std::pair<double, double>> rattle_space_m;
  bool impact;
  std::vector<double> levels;
  std::string level_name;
};

// The CLI's options and checks (analyse_command.cc), in the arguments' names.
study::RecordingAnalysisOptions options_of(const AnalyseArguments& a) {
  study::RecordingAnalysisOptions options;
  options.channels = a.channels;
  options.weighting.by_channel_name = a.weighting == "auto";
  if (a.weighting != "auto" && a.weighting != "none") {
    try {
      options.weighting.weighting = comfort::parse_weighting(a.weighting);
    } catch (const InputError& e) {
      throw InputError(fmt::format("weighting: {} (or auto, none)", e.what()));
    }
  }
  options.band_low_Hz = a.band_Hz.first;
  options.band_high_Hz = a.band_Hz.second;
  options.welch.segment_length_s = a.segment_s;
  options.welch.overlap_fraction = a.overlap;
  options.welch.detrend = signal::parse_detrend(a.detrend);
  if (a.smooth_bins < 1) {
    throw InputError(
        fmt::format("smooth_bins {}: expected an odd number of bins >= 1", a.smooth_bins));
  }
  options.smoothing_bins = static_cast<std::size_t>(a.smooth_bins);
  options.confidence = a.confidence;
  if (a.static_tyre_load_N) options.static_tyre_load_N = *a.static_tyre_load_N;
  if (a.model) {
    if (options.static_tyre_load_N) {
      throw InputError("model and static_tyre_load_N both set the static load; give one");
    }
    options.static_tyre_load_N =
        comfort::static_tyre_load_N(a.model->quarter_car("analyse").parameters);
  }
  if (a.rattle_space_m) {
    const auto [compression, rebound] = *a.rattle_space_m;
    if (!(compression > 0.0) || !(rebound > 0.0) || !std::isfinite(compression) ||
        !std::isfinite(rebound)) {
      throw InputError(
          "rattle_space_m: expected two distances > 0 in m, (COMPRESSION, REBOUND), e.g. "
          "(0.08, 0.09)");
    }
    options.rattle_space = comfort::RattleSpace{compression, rebound};
  }
  options.impact_hardness = a.impact;
  options.validate();
  return options;
}

py::object analyse(const AnalyseArguments& a) {
  const study::RecordingAnalysisOptions options = options_of(a);
  if (a.level_name.empty() ||
      a.level_name.find_first_not_of(
          "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") != std::string::npos) {
    throw InputError(fmt::format(
        "level_name '{}': use letters, digits and underscores (it names CSV columns), e.g. "
        "coulomb_force_N",
        a.level_name));
  }
  if (!a.levels.empty() && a.levels.size() != a.files.size()) {
    throw InputError(
        fmt::format("levels: {} values for {} recordings; give one level per "
                    "recording, in the order of the recordings",
                    a.levels.size(), a.files.size()));
  }
  for (double level : a.levels) {
    if (!std::isfinite(level)) {
      throw InputError(fmt::format("levels: {} is not a finite number", level));
    }
  }
  if (a.files.empty()) throw InputError("recordings: give at least one");
  std::vector<study::Recording> recordings;
  for (const auto& file : a.files) recordings.push_back(study::load_recording(file));
  std::optional<study::ParameterLevels> levels;
  study::RecordingAnalysis analysis;
  {
    py::gil_scoped_release unlocked;
    analysis = study::analyse_recordings(recordings, options);
    if (!a.levels.empty()) {
      levels = study::ParameterLevels{a.level_name, a.levels,
                                      study::correlate_with_levels(analysis, a.levels)};
    }
  }
  py::dict result = to_python(study::to_json(analysis, options, levels));
  py::dict spectra;
  for (auto& s : analysis.spectra) {
    py::dict spectrum;
    spectrum["unit"] = s.psd_unit;
    spectrum["frequency_Hz"] = to_numpy(std::move(s.psd.frequency_Hz));
    spectrum["psd"] = to_numpy(std::move(s.psd.psd));
    spectrum["lower"] = to_numpy(std::move(s.interval.lower));
    spectrum["upper"] = to_numpy(std::move(s.interval.upper));
    spectra[py::str(s.name)] = spectrum;
  }
  result["spectra"] = spectra;
  return result;
}

}  // namespace

void bind_analyse(py::module_& m) {
  m.def(
      "_analyse",
      [](std::vector<std::string> files, std::vector<std::string> channels, std::string weighting,
         std::pair<double, double> band_Hz, double segment_s, double overlap, std::string detrend,
         int smooth_bins, double confidence, std::optional<double> static_tyre_load_N,
         const ModelHandle* model, std::optional<std::pair<double, double>> rattle_space_m,
         bool impact, std::vector<double> levels, std::string level_name) {
        const AnalyseArguments a{std::move(files),
                                 std::move(channels),
                                 std::move(weighting),
                                 band_Hz,
                                 segment_s,
                                 overlap,
                                 std::move(detrend),
                                 smooth_bins,
                                 confidence,
                                 static_tyre_load_N,
                                 model,
                                 rattle_space_m,
                                 impact,
                                 std::move(levels),
                                 std::move(level_name)};
        return analyse(a);
      },
      "ridefit.analyse without its defaults");
}

}  // namespace ridefit::python
