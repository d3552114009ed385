#pragma once

#include <memory>
#include <optional>
#include <string>

#include "ridefit/model/half_car.h"
#include "ridefit/model/quarter_car.h"
#include "ridefit/road/excitation_file.h"
#include "ridefit/road/road_input.h"
#include "ridefit/simulate/integrator.h"
#include "ridefit/study/half_car_metrics.h"
#include "ridefit/study/quarter_car_metrics.h"

namespace ridefit::study {

// How a car is evaluated on a road. kAuto: in the frequency domain when that is exact (a linear
// car on a random road with a spectrum), by simulation otherwise; kFrequency insists on the
// frequency domain (InputError when it is not exact); kTime always simulates.
enum class EvaluationMethod { kAuto, kFrequency, kTime };

// The road of one load case, made once and shared by every evaluation on it: the same
// realisation of a random road every time (common random numbers), so that a metric is a
// smooth function of the design and differences between designs are not road noise.
struct LoadCaseRoad {
  std::optional<road::RoadSpectrum> spectrum;  // random roads (iso8608, power_law)
  std::shared_ptr<const road::RoadInput> input;
};

struct LoadCaseSettings {
  EvaluationMethod method = EvaluationMethod::kAuto;
  std::size_t frequency_points = 1000;  // log-spaced over the road's band
  // Time domain (and the frequency domain's expected peaks, over duration − settle).
  double output_rate_Hz = 1000.0;
  double settle_s = 2.0;
  double duration_s = 0.0;  // 0: the road's own
  simulate::IntegratorOptions integrator;
};

// The one decision, with the one error text: true for the frequency domain. `where` (the study
// file, a road) starts the message.
bool in_frequency_domain(bool linear_car, const LoadCaseRoad& road,
                         const LoadCaseSettings& settings, const std::string& where);

struct QuarterCarEvaluation {
  QuarterCarMetrics metrics;
  bool frequency_domain = false;
};

struct HalfCarEvaluation {
  HalfCarMetrics metrics;
  // Largest |travel|: in the frequency domain the expected largest of the Gaussian response over
  // the evaluated duration (signal/expected_peak.h), in the time domain the largest after
  // settling.
  double front_travel_peak_m = 0.0;
  double rear_travel_peak_m = 0.0;
  bool frequency_domain = false;
};

// A car on one load case: the metrics the CLI's sweep, the optimiser and the examples report.
QuarterCarEvaluation evaluate_on_load_case(const model::QuarterCar& car, const LoadCaseRoad& road,
                                           const LoadCaseSettings& settings,
                                           const std::string& where);
HalfCarEvaluation evaluate_on_load_case(const model::HalfCar& car, const LoadCaseRoad& road,
                                        const LoadCaseSettings& settings, const std::string& where);

}  // namespace ridefit::study
