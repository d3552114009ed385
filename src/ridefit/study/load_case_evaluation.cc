#include "ridefit/study/load_case_evaluation.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "ridefit/common/errors.h"
#include "ridefit/signal/expected_peak.h"
#include "ridefit/simulate/half_car_simulation.h"
#include "ridefit/simulate/half_car_state_space.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "ridefit/study/half_car_spectral_metrics.h"
#include "ridefit/study/quarter_car_spectral_metrics.h"

namespace ridefit::study {
namespace {

double peak_after(const std::vector<double>& time_s, const std::vector<double>& values,
                  double settle_s) {
  double peak = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (time_s[i] >= settle_s) peak = std::max(peak, std::abs(values[i]));
  }
  return peak;
}

// The record a time-domain run would evaluate: the settings' duration (or the road's) less the
// settling time.
double evaluated_duration_s(const LoadCaseSettings& settings, const road::RoadSpectrum& road) {
  const double length = settings.duration_s > 0.0 ? settings.duration_s : road.duration_s;
  return length - settings.settle_s;
}

simulate::SimulationOptions simulation_options(const LoadCaseSettings& settings) {
  simulate::SimulationOptions options;
  options.output_rate_Hz = settings.output_rate_Hz;
  options.duration_s = settings.duration_s;
  options.integrator = settings.integrator;
  return options;
}

}  // namespace

bool in_frequency_domain(bool linear_car, const LoadCaseRoad& road,
                         const LoadCaseSettings& settings, const std::string& where) {
  const bool exact = linear_car && road.spectrum.has_value();
  if (settings.method == EvaluationMethod::kFrequency && !exact) {
    throw InputError(fmt::format(
        "{}: method frequency needs a linear car (no Dahl friction: damper_state slip or stick "
        "or a passive axle; symmetric dampers; no optional nonlinear effect, no control law) and "
        "a random road with a spectrum (iso8608, power_law){}",
        where,
        linear_car ? "; this road has no spectrum"
                   : "; this car is not linear (use method auto "
                     "or time)"));
  }
  return exact && settings.method != EvaluationMethod::kTime;
}

QuarterCarEvaluation evaluate_on_load_case(const model::QuarterCar& car, const LoadCaseRoad& road,
                                           const LoadCaseSettings& settings,
                                           const std::string& where) {
  QuarterCarEvaluation result;
  result.frequency_domain = in_frequency_domain(car.is_linear(), road, settings, where);
  if (result.frequency_domain) {
    // quarter_car_spectral_metrics takes the settling time off the road's own duration.
    const double settle =
        road.spectrum->duration_s - evaluated_duration_s(settings, *road.spectrum);
    result.metrics =
        quarter_car_spectral_metrics(car, *road.spectrum, settings.frequency_points, settle);
    return result;
  }
  const auto response = simulate::simulate(car, *road.input, simulation_options(settings));
  result.metrics = quarter_car_metrics(response, car.parameters(), settings.settle_s);
  return result;
}

HalfCarEvaluation evaluate_on_load_case(const model::HalfCar& car, const LoadCaseRoad& road,
                                        const LoadCaseSettings& settings,
                                        const std::string& where) {
  HalfCarEvaluation result;
  result.frequency_domain = in_frequency_domain(car.is_linear(), road, settings, where);
  if (result.frequency_domain) {
    const auto spectra = half_car_spectra(car, *road.spectrum, settings.frequency_points);
    result.metrics = half_car_spectral_metrics(spectra, car.parameters());
    auto expected_peak = [&](simulate::HalfCarLinearOutput output) {
      const auto& psd = spectra.psd[static_cast<std::size_t>(output)];
      return signal::expected_gaussian_peak(signal::spectral_moment(spectra.frequency_Hz, psd, 0),
                                            signal::spectral_moment(spectra.frequency_Hz, psd, 2),
                                            evaluated_duration_s(settings, *road.spectrum));
    };
    result.front_travel_peak_m = expected_peak(simulate::kFrontTravel);
    result.rear_travel_peak_m = expected_peak(simulate::kRearTravel);
    return result;
  }
  simulate::HalfCarSimulationOptions options;
  static_cast<simulate::SimulationOptions&>(options) = simulation_options(settings);
  const auto response = simulate::simulate(car, *road.input, options);
  const double settle = settings.settle_s;
  result.metrics = half_car_metrics(response, car.parameters(), settle);
  result.front_travel_peak_m =
      peak_after(response.time_s, response.channel(&model::HalfCarOutputs::front_travel_m), settle);
  result.rear_travel_peak_m =
      peak_after(response.time_s, response.channel(&model::HalfCarOutputs::rear_travel_m), settle);
  return result;
}

}  // namespace ridefit::study
