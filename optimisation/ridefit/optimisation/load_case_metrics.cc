#include "ridefit/optimisation/load_case_metrics.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "ridefit/io/input_error.h"
#include "ridefit/signal/expected_peak.h"
#include "ridefit/simulate/half_car_simulation.h"
#include "ridefit/simulate/half_car_state_space.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "ridefit/study/half_car_metrics.h"
#include "ridefit/study/half_car_spectral_metrics.h"
#include "ridefit/study/quarter_car_metrics.h"
#include "ridefit/study/quarter_car_spectral_metrics.h"

namespace ridefit::optimisation {
namespace {

double peak_after(const std::vector<double>& time_s, const std::vector<double>& values,
                  double settle_s) {
  double peak = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (time_s[i] >= settle_s) peak = std::max(peak, std::abs(values[i]));
  }
  return peak;
}

std::vector<double> values_of(const std::vector<std::pair<std::string, double>>& named) {
  std::vector<double> values;
  for (const auto& [name, value] : named) values.push_back(value);
  return values;
}

// The record a time-domain run would evaluate: the study's duration (or the road's) less the
// settling time (checked to leave at least 1 s when the study was read).
double evaluated_duration_s(const TuningStudy& study, const road::RoadSpectrum& road) {
  const double length =
      study.evaluation.duration_s > 0.0 ? study.evaluation.duration_s : road.duration_s;
  return length - study.evaluation.settle_s;
}

// quarter_car_spectral_metrics takes the settling time off the road's own duration.
double settle_for_peak(const TuningStudy& study, const road::RoadSpectrum& road) {
  return road.duration_s - evaluated_duration_s(study, road);
}

simulate::IntegratorOptions integrator(const TuningStudy& study, Accuracy accuracy) {
  simulate::IntegratorOptions options;
  options.relative_tolerance = accuracy == Accuracy::kVerify
                                   ? study.evaluation.verify_relative_tolerance
                                   : study.evaluation.relative_tolerance;
  return options;
}

LoadCaseMetrics quarter_car_case(const TuningStudy& study, const io::QuarterCarFile& file,
                                 const LoadCaseRoad& road, Accuracy accuracy,
                                 bool frequency_allowed) {
  const model::QuarterCar car = file.make_model();
  const bool exact = car.is_linear() && road.spectrum.has_value();
  if (study.evaluation.method == EvaluationMethod::kFrequency && !exact) {
    throw InputError(fmt::format(
        "{}: evaluation method frequency needs a linear car (damper_state slip or stick, symmetric "
        "damper) and "
        "random roads (iso8608, power_law)",
        study.study_file.string()));
  }
  if (exact && frequency_allowed && study.evaluation.method != EvaluationMethod::kTime) {
    const int factor = accuracy == Accuracy::kVerify ? 4 : 1;
    return {values_of(study::quarter_car_spectral_metrics(
                          car, *road.spectrum,
                          static_cast<std::size_t>(study.evaluation.frequency_points * factor),
                          settle_for_peak(study, *road.spectrum))
                          .named()),
            true};
  }
  simulate::SimulationOptions options;
  options.output_rate_Hz = study.evaluation.output_rate_Hz;
  options.duration_s = study.evaluation.duration_s;
  options.integrator = integrator(study, accuracy);
  const auto response = simulate::simulate(car, *road.input, options);
  return {
      values_of(
          study::quarter_car_metrics(response, file.parameters, study.evaluation.settle_s).named()),
      false};
}

LoadCaseMetrics half_car_case(const TuningStudy& study, const io::HalfCarFile& file,
                              const LoadCaseRoad& road, Accuracy accuracy, bool frequency_allowed) {
  const model::HalfCar car = file.make_model();
  const bool exact = car.is_linear() && road.spectrum.has_value();
  if (study.evaluation.method == EvaluationMethod::kFrequency && !exact) {
    throw InputError(fmt::format(
        "{}: evaluation method frequency needs a linear car (no Dahl friction, passive damping, "
        "symmetric dampers) and random roads (iso8608, power_law)",
        study.study_file.string()));
  }
  LoadCaseMetrics result;
  if (exact && frequency_allowed && study.evaluation.method != EvaluationMethod::kTime) {
    const int factor = accuracy == Accuracy::kVerify ? 4 : 1;
    const auto spectra = study::half_car_spectra(
        car, *road.spectrum, static_cast<std::size_t>(study.evaluation.frequency_points * factor));
    result.values = values_of(study::half_car_spectral_metrics(spectra, file.parameters).named());
    for (auto output : {simulate::kFrontTravel, simulate::kRearTravel}) {
      const auto& psd = spectra.psd[static_cast<std::size_t>(output)];
      result.values.push_back(
          signal::expected_gaussian_peak(signal::spectral_moment(spectra.frequency_Hz, psd, 0),
                                         signal::spectral_moment(spectra.frequency_Hz, psd, 2),
                                         evaluated_duration_s(study, *road.spectrum)));
    }
    result.frequency_domain = true;
    return result;
  }
  simulate::HalfCarSimulationOptions options;
  options.output_rate_Hz = study.evaluation.output_rate_Hz;
  options.duration_s = study.evaluation.duration_s;
  options.integrator = integrator(study, accuracy);
  const auto response = simulate::simulate(car, *road.input, options);
  const double settle = study.evaluation.settle_s;
  result.values = values_of(study::half_car_metrics(response, file.parameters, settle).named());
  result.values.push_back(peak_after(
      response.time_s, response.channel(&model::HalfCarOutputs::front_travel_m), settle));
  result.values.push_back(
      peak_after(response.time_s, response.channel(&model::HalfCarOutputs::rear_travel_m), settle));
  return result;
}

}  // namespace

LoadCaseRoad prepare_load_case_road(const TuningStudy& study, std::size_t load_case) {
  const LoadCase& c = study.load_cases[load_case];
  LoadCaseRoad road;
  try {
    road.spectrum = road::load_road_spectrum(c.road_file, c.speed_m_per_s);
    road.input = c.speed_m_per_s ? road::load_excitation(c.road_file, *c.speed_m_per_s)
                                 : road::load_excitation(c.road_file);
  } catch (const InputError& e) {
    throw InputError(
        fmt::format("{}: load case '{}': {}", study.study_file.string(), c.name, e.what()));
  }
  return road;
}

LoadCaseMetrics evaluate_load_case(const TuningStudy& study, const TuningModel& model,
                                   const LoadCaseRoad& road, Accuracy accuracy,
                                   bool frequency_allowed) {
  LoadCaseMetrics result =
      model.quarter ? quarter_car_case(study, *model.quarter, road, accuracy, frequency_allowed)
                    : half_car_case(study, *model.half, road, accuracy, frequency_allowed);
  for (std::size_t m = 0; m < result.values.size(); ++m) {
    if (!std::isfinite(result.values[m])) {
      throw RunError(fmt::format("metric {} is {} (the run diverged)", metric_names(study.kind)[m],
                                 result.values[m]));
    }
  }
  return result;
}

}  // namespace ridefit::optimisation
